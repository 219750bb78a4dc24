#pragma once
// Per-element projection of a symmetric Hessian block onto the positive-definite matrices, so that
// the assembled Hessian is positive semi-definite and Newton steps descend.
//
// Modes (eigenvalues k_i of the block H):
//   kClamp    k_i := max(k_i, epsilon)                      (TinyAD's default)
//   kAbs      k_i := max(|k_i|, epsilon)                    (mirror negative curvature)
//   kShift    H := H + (epsilon - min k_i) I if min k_i < epsilon
//             (the paper's Hessian modification, step 1 of section 4.4, with epsilon = 1e-8)
//   kNone     H unchanged
// A block is left unchanged, without an eigen-decomposition, when Gershgorin's theorem already
// proves every eigenvalue >= epsilon: H_ii - sum_{j != i} |H_ij| >= epsilon for every row i.

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>

#include "optim/types.h"

namespace sa {

enum class ProjectionMode { kClamp, kAbs, kShift, kNone };

std::string to_string(ProjectionMode mode);
/// "clamp", "abs", "shift" or "none"; throws InvalidArgumentError otherwise.
ProjectionMode parse_projection(const std::string& name);

/// True when every Gershgorin disc of `h` lies in [epsilon, inf).
template <int N>
bool is_diagonally_dominant_above(const Mat<N>& h, double epsilon) {
    for (int i = 0; i < h.rows(); ++i) {
        double off = 0.0;
        for (int j = 0; j < h.cols(); ++j) {
            if (j != i) off += std::abs(h(i, j));
        }
        if (h(i, i) - off < epsilon) return false;
    }
    return true;
}

/// Blocks larger than this are eigen-decomposed by one dynamic-size solver compiled once, in
/// hessian_projection.cpp: a fixed-size SelfAdjointEigenSolver per arity above a dozen or so is
/// slow to compile and needs gigabytes of compiler memory (BENCHMARKS.md, "CI time (session
/// 47)"), and elements that large (the boundary-angle barrier's fans, up to 48 variables) are few.
inline constexpr int kLargestFixedSizeProjection = 12;

namespace detail {

/// The eigen-decomposition part of project_hessian_block() on a square matrix type (fixed or
/// dynamic size).
template <class Matrix>
bool project_by_eigenvalues(Matrix& h, ProjectionMode mode, double epsilon) {
    if (mode == ProjectionMode::kShift) {
        Eigen::SelfAdjointEigenSolver<Matrix> eig(h, Eigen::EigenvaluesOnly);
        const double smallest = eig.eigenvalues()(0);
        if (smallest >= epsilon) return false;
        h.diagonal().array() += epsilon - smallest;
        return true;
    }
    Eigen::SelfAdjointEigenSolver<Matrix> eig(h);
    typename Eigen::SelfAdjointEigenSolver<Matrix>::RealVectorType values = eig.eigenvalues();
    bool changed = false;
    for (int i = 0; i < values.size(); ++i) {
        double v = mode == ProjectionMode::kAbs ? std::abs(values(i)) : values(i);
        v = std::max(v, epsilon);
        changed |= v != values(i);
        values(i) = v;
    }
    if (changed) h = eig.eigenvectors() * values.asDiagonal() * eig.eigenvectors().transpose();
    return changed;
}

/// project_by_eigenvalues() on the n x n column-major block at `h`, with a dynamic-size solver.
bool project_large_block_by_eigenvalues(double* h, int n, ProjectionMode mode, double epsilon);

}  // namespace detail

/// Projects the symmetric block `h` in place (see the modes above). Returns true when `h` was
/// changed. A block with a non-finite entry is left as it is and reported as unchanged; the caller
/// checks finiteness.
template <int N>
bool project_hessian_block(Mat<N>& h, ProjectionMode mode, double epsilon) {
    if (mode == ProjectionMode::kNone) return false;
    if (is_diagonally_dominant_above<N>(h, epsilon)) return false;
    if (!h.allFinite()) return false;
    if constexpr (N > kLargestFixedSizeProjection) {
        return detail::project_large_block_by_eigenvalues(h.data(), N, mode, epsilon);
    } else {
        return detail::project_by_eigenvalues(h, mode, epsilon);
    }
}

}  // namespace sa
