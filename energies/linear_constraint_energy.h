#pragma once
// A generic linear constraint term for Ẽ_assembly (ENGINE-SPEC's "generic linear constraint
// term"): per element, R rows of coefficients over the element's N variables and a right-hand
// side,
//     E_e(x) = |C_e x - b_e|^2,     C_e: R x N,  b_e: R,
// a sum of squares of linear functions: quadratic (constant Hessian 2 C_e^T C_e) and convex, so
// the optimizer assembles and factors its pattern once and never projects it. Whatever a user
// writes as "these variables satisfy C x = b" goes through it: PolyCube planarity a^T A_i e = 0
// (frontends/polycube/polycube_constraints.h), a vertex sliding on a plane or a line, a vertex kept
// on a plane in the vertex stage. Weighted by lambda like the other assembly terms; scale each row
// so that its residual has the units of the others (unit edges, as Eq. 7 does).

#include <string>
#include <vector>

#include "optim/errors.h"
#include "optim/types.h"

namespace sa {

template <int N, int R>
struct LinearConstraintRows {
    Eigen::Matrix<double, R, N> coefficients = Eigen::Matrix<double, R, N>::Zero();
    Vec<R> rhs = Vec<R>::Zero();
};

template <int N, int R>
class LinearConstraintEnergy {
  public:
    static constexpr int arity = N;
    static constexpr bool is_quadratic = true;
    static constexpr bool is_convex = true;
    using Rows = LinearConstraintRows<N, R>;

    /// One element per entry of `rows`. Throws InvalidArgumentError on a non-finite entry.
    explicit LinearConstraintEnergy(std::vector<Rows> rows) : rows_(std::move(rows)) {
        for (std::size_t e = 0; e < rows_.size(); ++e) {
            if (!rows_[e].coefficients.allFinite() || !rows_[e].rhs.allFinite()) {
                throw InvalidArgumentError("LinearConstraintEnergy: element " + std::to_string(e) +
                                           " has a non-finite coefficient");
            }
        }
    }

    /// The residual C_e x - b_e.
    Vec<R> residual(Index e, const Vec<N>& x) const {
        return rows_[e].coefficients * x - rows_[e].rhs;
    }
    double value(Index e, const Vec<N>& x) const { return residual(e, x).squaredNorm(); }
    double value_gradient(Index e, const Vec<N>& x, Vec<N>& gradient) const {
        const Vec<R> r = residual(e, x);
        gradient.noalias() = 2.0 * rows_[e].coefficients.transpose() * r;
        return r.squaredNorm();
    }
    double value_gradient_hessian(Index e, const Vec<N>& x, Vec<N>& gradient,
                                  Mat<N>& hessian) const {
        hessian.noalias() = 2.0 * rows_[e].coefficients.transpose() * rows_[e].coefficients;
        return value_gradient(e, x, gradient);
    }

    const std::vector<Rows>& rows() const { return rows_; }

  private:
    std::vector<Rows> rows_;
};

}  // namespace sa
