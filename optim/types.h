#pragma once
// Basic index and small fixed-size matrix types shared by every layer.

#include <Eigen/Core>
#include <Eigen/LU>  // determinant() and inverse() of the fixed-size matrices used everywhere
#include <cstdint>
#include <limits>

namespace sa {

/// Index of a variable, an element or a vertex. 32 bits: problems have fewer than 2^31
/// variables, and element tables are the largest arrays we keep.
using Index = int;

/// Fixed-size column vector and square matrix used by element energies of arity N.
template <int N>
using Vec = Eigen::Matrix<double, N, 1>;
template <int N>
using Mat = Eigen::Matrix<double, N, N>;

/// Views of dynamic-size vectors and matrices, which bind to Eigen::VectorXd, Eigen::MatrixXd
/// and Eigen::Map's of raw memory alike: an element of run-time arity (dynamic_element_energy.h)
/// sees its variables, gradient and Hessian through them.
using ConstVectorRef = Eigen::Ref<const Eigen::VectorXd>;
using VectorRef = Eigen::Ref<Eigen::VectorXd>;
using MatrixRef = Eigen::Ref<Eigen::MatrixXd>;

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace sa
