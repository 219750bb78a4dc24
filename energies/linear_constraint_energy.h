#pragma once
// A generic linear constraint as an assembly term: per element, R rows over its N variables,
//     |C_e x - b_e|^2,     C_e an R x N matrix, b_e in R^R,
// squared into E~_assembly and weighted by lambda like Eqs. 7-9. Everything the paper's assembly
// terms say is of this form, and so is what a user adds: "these vertices stay on a plane"
// (n^T A_s (u_b - u_a) = 0 for the rest edges between them), PolyCube's planarity
// (a_axis^T A_i e = 0 on a chart's facet edges), a vertex sliding on a plane (n^T (A_s u + T_s)
// = c). Quadratic and convex: its Hessian 2 C_e^T C_e is assembled once and never projected.

#include <vector>

#include "optim/types.h"

namespace sa {

template <int R, int N>
class LinearConstraintEnergy {
  public:
    static constexpr int arity = N;
    static constexpr bool is_quadratic = true;
    static constexpr bool is_convex = true;  // a sum of squares of linear functions

    using Coefficients = Eigen::Matrix<double, R, N>;

    LinearConstraintEnergy(std::vector<Coefficients> coefficients, std::vector<Vec<R>> rhs)
        : coefficients_(std::move(coefficients)), rhs_(std::move(rhs)) {}

    /// C_e x - b_e.
    Vec<R> residual(Index e, const Vec<N>& x) const { return coefficients_[e] * x - rhs_[e]; }

    double value(Index e, const Vec<N>& x) const { return residual(e, x).squaredNorm(); }
    double value_gradient(Index e, const Vec<N>& x, Vec<N>& g) const {
        const Vec<R> r = residual(e, x);
        g.noalias() = 2.0 * coefficients_[e].transpose() * r;
        return r.squaredNorm();
    }
    double value_gradient_hessian(Index e, const Vec<N>& x, Vec<N>& g, Mat<N>& h) const {
        h.noalias() = 2.0 * coefficients_[e].transpose() * coefficients_[e];
        return value_gradient(e, x, g);
    }

    Index size() const { return static_cast<Index>(rhs_.size()); }
    const Coefficients& coefficients(Index e) const { return coefficients_[e]; }
    const Vec<R>& rhs(Index e) const { return rhs_[e]; }

  private:
    std::vector<Coefficients> coefficients_;
    std::vector<Vec<R>> rhs_;
};

}  // namespace sa
