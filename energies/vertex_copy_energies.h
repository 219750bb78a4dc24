#pragma once
// Energies of vertex-variable Simplex Assembly (v-SA, section 5.1): every simplex owns copies of
// its D + 1 vertices (D (D + 1) variables), its linear part is
//     A_i = [x_1 - x_0 | ... | x_D - x_0] R_i^-1,      R_i = the rest edge matrix,
// and assembly asks the copies of each vertex to coincide.
//
//   VertexSimplexEnergy          a per-simplex energy of A (SimplexEnergy by default, or any
//                                element energy of arity D*D: a user's, a re-indexed one),
//                                composed with the linear map copies -> vec(A_i). The same adapter
//                                serves v-SA's copies and the vertex stage's positions (A = X E^-1)
//   VertexCopyAgreementEnergy    |x_a - x_b|^2 between two copies of one vertex (quadratic)
//   VertexCopyTargetEnergy       |x - v*|^2 for a copy of a handle (quadratic)

#include <vector>

#include "energies/simplex_energy.h"
#include "optim/element_energy.h"

namespace sa {

template <int D, ElementEnergy E = SimplexEnergy<D>>
class VertexSimplexEnergy {
  public:
    static_assert(E::arity == D * D, "VertexSimplexEnergy wraps an energy of vec(A)");
    static constexpr int arity = D * (D + 1);
    static constexpr int kA = D * D;
    // A linear change of variables keeps a constant Hessian constant and a convex energy convex.
    static constexpr bool is_quadratic = is_quadratic_energy<E>();
    static constexpr bool is_convex = is_convex_energy<E>();

    /// `rest_edge_inverses[i]` = R_i^-1 for each element i; element i of `energy` is evaluated at
    /// A_i.
    VertexSimplexEnergy(E energy, std::vector<Mat<D>> rest_edge_inverses)
        : energy_(std::move(energy)), rest_inverse_(std::move(rest_edge_inverses)) {}

    double value(Index i, const Vec<arity>& x) const {
        return energy_.value(i, linear_part(weights(i), x));
    }
    double value_gradient_hessian(Index i, const Vec<arity>& x, Vec<arity>& g,
                                  Mat<arity>& h) const {
        const Weights W = weights(i);
        Vec<kA> ga;
        Mat<kA> ha;
        const double v = energy_.value_gradient_hessian(i, linear_part(W, x), ga, ha);
        for (int p = 0; p <= D; ++p) {
            g.template segment<D>(D * p) = W(p, 0) * ga.template segment<D>(0);
            for (int c = 1; c < D; ++c)
                g.template segment<D>(D * p) += W(p, c) * ga.template segment<D>(D * c);
        }
        h = transformed(W, ha);
        return v;
    }
    /// Projects in A: the Hessian is L^T H_A L with vec(A_i) = L x (L = W^T kron I, W below),
    /// and L^T P(H_A) L is positive semidefinite whenever P(H_A) is (Smith, De Goes and Kim 2019
    /// do the same). It is not the eigenvalue projection of the D(D+1) x D(D+1) block: L's null
    /// space (translations of the simplex) keeps eigenvalue 0 instead of epsilon, and the rest is
    /// clamped in A's metric. One 9 x 9 (4 x 4) projection through the singular vectors of A
    /// instead of a 12 x 12 (6 x 6) eigen-decomposition. An energy without a projection of its own
    /// gets the eigenvalue projection of its D^2 x D^2 block (project_hessian_block()).
    bool project_hessian(Index i, const Vec<arity>& x, Mat<arity>& h, ProjectionMode mode,
                         double epsilon) const {
        const Weights W = weights(i);
        const Vec<kA> a = linear_part(W, x);
        Vec<kA> ga;
        Mat<kA> ha;
        energy_.value_gradient_hessian(i, a, ga, ha);
        bool changed;
        if constexpr (HasOwnProjection<E>) {
            changed = energy_.project_hessian(i, a, ha, mode, epsilon);
        } else {
            changed = project_hessian_block<kA>(ha, mode, epsilon);
        }
        if (!changed) return false;
        h = transformed(W, ha);
        return true;
    }
    double max_step(Index i, const Vec<arity>& x,
                    const Vec<arity>& dx) const requires HasMaxStep<E> {
        const Weights W = weights(i);
        return energy_.max_step(i, linear_part(W, x), linear_part(W, dx));
    }
    const E& inner() const { return energy_; }

  private:
    /// A_i = [x_0 | ... | x_D] W: row 0 of W is minus the sum of R_i^-1's rows, row k + 1 is row
    /// k of R_i^-1 (column c of A = sum_k (x_{k+1} - x_0) R^-1(k, c)).
    using Weights = Eigen::Matrix<double, D + 1, D>;
    Weights weights(Index i) const {
        const Mat<D>& Rinv = rest_inverse_[i];
        Weights W;
        W.template bottomRows<D>() = Rinv;
        W.row(0) = -Rinv.colwise().sum();
        return W;
    }
    /// vec(A) = L x, column c of A = sum_p W(p, c) x_p.
    static Vec<kA> linear_part(const Weights& W, const Vec<arity>& x) {
        Vec<kA> a;
        for (int c = 0; c < D; ++c) {
            a.template segment<D>(D * c) = W(0, c) * x.template segment<D>(0);
            for (int p = 1; p <= D; ++p)
                a.template segment<D>(D * c) += W(p, c) * x.template segment<D>(D * p);
        }
        return a;
    }
    /// L^T H_A L by the structure of L = W^T kron I: the D x D block (p, q) is
    /// sum_{c, e} W(p, c) W(q, e) H_A(block c, block e), summed over c first: a third of the
    /// multiplications of the dense product L^T H_A L.
    static Mat<arity> transformed(const Weights& W, const Mat<kA>& ha) {
        Eigen::Matrix<double, arity, kA> T;  // block (p, e) = sum_c W(p, c) H_A(block c, e)
        for (int p = 0; p <= D; ++p) {
            for (int e = 0; e < D; ++e) {
                auto t = T.template block<D, D>(D * p, D * e);
                t = W(p, 0) * ha.template block<D, D>(0, D * e);
                for (int c = 1; c < D; ++c) t += W(p, c) * ha.template block<D, D>(D * c, D * e);
            }
        }
        Mat<arity> h;
        for (int q = 0; q <= D; ++q) {
            for (int p = 0; p <= D; ++p) {
                auto b = h.template block<D, D>(D * p, D * q);
                b = W(q, 0) * T.template block<D, D>(D * p, 0);
                for (int e = 1; e < D; ++e) b += W(q, e) * T.template block<D, D>(D * p, D * e);
            }
        }
        return h;
    }

    E energy_;
    std::vector<Mat<D>> rest_inverse_;
};

template <int D>
struct VertexCopyAgreementEnergy {
    static constexpr int arity = 2 * D;
    static constexpr bool is_quadratic = true;
    static constexpr bool is_convex = true;  // a sum of squares of linear functions
    double value(Index, const Vec<arity>& x) const {
        return (x.template head<D>() - x.template tail<D>()).squaredNorm();
    }
    double value_gradient_hessian(Index i, const Vec<arity>& x, Vec<arity>& g,
                                  Mat<arity>& h) const {
        const Vec<D> r = x.template head<D>() - x.template tail<D>();
        g << 2.0 * r, -2.0 * r;
        const Mat<D> I = 2.0 * Mat<D>::Identity();
        h << I, -I, -I, I;
        return value(i, x);
    }
};

template <int D>
struct VertexCopyTargetEnergy {
    static constexpr int arity = D;
    static constexpr bool is_quadratic = true;
    static constexpr bool is_convex = true;  // a sum of squares of linear functions
    std::vector<Vec<D>> targets;
    double value(Index i, const Vec<D>& x) const { return (x - targets[i]).squaredNorm(); }
    double value_gradient_hessian(Index i, const Vec<D>& x, Vec<D>& g, Mat<D>& h) const {
        g = 2.0 * (x - targets[i]);
        h = 2.0 * Mat<D>::Identity();
        return value(i, x);
    }
};

}  // namespace sa
