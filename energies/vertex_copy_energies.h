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

    double value(Index i, const Vec<arity>& x) const { return energy_.value(i, map(i) * x); }
    double value_gradient_hessian(Index i, const Vec<arity>& x, Vec<arity>& g,
                                  Mat<arity>& h) const {
        const Eigen::Matrix<double, kA, arity> L = map(i);
        Vec<kA> ga;
        Mat<kA> ha;
        const double v = energy_.value_gradient_hessian(i, L * x, ga, ha);
        g = L.transpose() * ga;
        h = L.transpose() * ha * L;
        return v;
    }
    /// Projects in A: the Hessian is L^T H_A L with L = map(i), and L^T P(H_A) L is positive
    /// semidefinite whenever P(H_A) is (Smith, De Goes and Kim 2019 do the same). It is not the
    /// eigenvalue projection of the D(D+1) x D(D+1) block: L's null space (translations of the
    /// simplex) keeps eigenvalue 0 instead of epsilon, and the rest is clamped in A's metric.
    /// One 9 x 9 (4 x 4) projection through the singular vectors of A instead of a 12 x 12
    /// (6 x 6) eigen-decomposition. An energy without a projection of its own gets the
    /// eigenvalue projection of its D^2 x D^2 block (project_hessian_block()).
    bool project_hessian(Index i, const Vec<arity>& x, Mat<arity>& h, ProjectionMode mode,
                         double epsilon) const {
        const Eigen::Matrix<double, kA, arity> L = map(i);
        const Vec<kA> a = L * x;
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
        h = L.transpose() * ha * L;
        return true;
    }
    double max_step(Index i, const Vec<arity>& x,
                    const Vec<arity>& dx) const requires HasMaxStep<E> {
        const Eigen::Matrix<double, kA, arity> L = map(i);
        return energy_.max_step(i, L * x, L * dx);
    }
    /// The linear map from the copies (x_0, ..., x_D) to vec(A_i).
    Eigen::Matrix<double, kA, arity> map(Index i) const {
        // vec(P R^-1) = (R^-T kron I) vec(P), vec(P) column c = x_{c+1} - x_0.
        Eigen::Matrix<double, kA, arity> L = Eigen::Matrix<double, kA, arity>::Zero();
        const Mat<D>& Rinv = rest_inverse_[i];
        for (int c = 0; c < D; ++c) {  // column c of A = sum_k (x_{k+1} - x_0) Rinv(k, c)
            for (int k = 0; k < D; ++k) {
                L.template block<D, D>(D * c, D * (k + 1)) += Rinv(k, c) * Mat<D>::Identity();
                L.template block<D, D>(D * c, 0) -= Rinv(k, c) * Mat<D>::Identity();
            }
        }
        return L;
    }

    const E& inner() const { return energy_; }

  private:
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
