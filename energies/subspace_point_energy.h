#pragma once
// An element energy of points, each point restricted to an affine subspace of its own: the element
// names P points by D variables each (arity P * D), and point k of element e is evaluated at
//     x_k = origin_p + basis_p q_k,      p = points[e][k],  basis_p: D x D,
// q_k the point's D variables. A basis column of zeros leaves its variable without effect (fix
// it in the Problem); the identity basis with a zero origin makes q the position itself. This is
// how a point slides: on a plane (two columns, the plane's tangent directions), along a line
// (one column), or not at all (no column), while the inner energy sees positions only. A linear
// change of variables: gradient B^T g, Hessian B^T H B, a projected Hessian stays positive
// semidefinite, and a feasible step of q is a feasible step of x.
//
// Every optional member of the inner energy (max_step, project_hessian) is forwarded.

#include <array>
#include <vector>

#include "optim/element_energy.h"
#include "optim/errors.h"

namespace sa {

template <int P, int D, ElementEnergy E>
class SubspacePointEnergy {
  public:
    static_assert(E::arity == P * D, "SubspacePointEnergy: the inner energy takes P points of D");
    static constexpr int arity = P * D;

    /// `points[e]`: the points of element e, indices into `origins` and `bases` (one per point).
    /// Throws InvalidArgumentError on mismatched sizes or an index out of range.
    SubspacePointEnergy(E energy, std::vector<std::array<Index, P>> points,
                        std::vector<Vec<D>> origins, std::vector<Mat<D>> bases)
        : energy_(std::move(energy)),
          points_(std::move(points)),
          origin_(std::move(origins)),
          basis_(std::move(bases)) {
        if (origin_.size() != basis_.size())
            throw InvalidArgumentError("SubspacePointEnergy: " + std::to_string(origin_.size()) +
                                       " origins but " + std::to_string(basis_.size()) + " bases");
        for (std::size_t e = 0; e < points_.size(); ++e) {
            for (Index p : points_[e]) {
                if (p < 0 || std::size_t(p) >= origin_.size())
                    throw InvalidArgumentError("SubspacePointEnergy: element " + std::to_string(e) +
                                               " names point " + std::to_string(p) + " of " +
                                               std::to_string(origin_.size()));
            }
        }
    }

    Index num_elements() const { return static_cast<Index>(points_.size()); }

    /// The positions x of element e's points at its variables q.
    Vec<arity> positions(Index e, const Vec<arity>& q) const {
        Vec<arity> x;
        for (int k = 0; k < P; ++k) {
            const Index p = points_[e][k];
            x.template segment<D>(D * k) = origin_[p] + basis_[p] * q.template segment<D>(D * k);
        }
        return x;
    }

    double value(Index e, const Vec<arity>& q) const { return energy_.value(e, positions(e, q)); }

    double value_gradient_hessian(Index e, const Vec<arity>& q, Vec<arity>& g,
                                  Mat<arity>& h) const {
        Vec<arity> gx;
        Mat<arity> hx;
        const double v = energy_.value_gradient_hessian(e, positions(e, q), gx, hx);
        g = transform_gradient(e, gx);
        h = transform_hessian(e, hx);
        return v;
    }

    bool project_hessian(Index e, const Vec<arity>& q, Mat<arity>& h, ProjectionMode mode,
                         double epsilon) const {
        const Vec<arity> x = positions(e, q);
        Vec<arity> gx;
        Mat<arity> hx;
        energy_.value_gradient_hessian(e, x, gx, hx);
        bool changed;
        if constexpr (HasOwnProjection<E>) {
            changed = energy_.project_hessian(e, x, hx, mode, epsilon);
        } else {
            changed = project_hessian_block<arity>(hx, mode, epsilon);
        }
        if (changed) h = transform_hessian(e, hx);
        return changed;
    }

    double max_step(Index e, const Vec<arity>& q,
                    const Vec<arity>& dq) const requires HasMaxStep<E> {
        Vec<arity> dx;
        for (int k = 0; k < P; ++k)
            dx.template segment<D>(D * k) = basis_[points_[e][k]] * dq.template segment<D>(D * k);
        return energy_.max_step(e, positions(e, q), dx);
    }

  private:
    Vec<arity> transform_gradient(Index e, const Vec<arity>& gx) const {
        Vec<arity> g;
        for (int k = 0; k < P; ++k)
            g.template segment<D>(D * k) =
                basis_[points_[e][k]].transpose() * gx.template segment<D>(D * k);
        return g;
    }
    Mat<arity> transform_hessian(Index e, const Mat<arity>& hx) const {
        Mat<arity> h;
        for (int a = 0; a < P; ++a) {
            const Mat<D>& Ba = basis_[points_[e][a]];
            for (int b = 0; b < P; ++b) {
                h.template block<D, D>(D * a, D * b) =
                    Ba.transpose() * hx.template block<D, D>(D * a, D * b) * basis_[points_[e][b]];
            }
        }
        return h;
    }

    E energy_;
    std::vector<std::array<Index, P>> points_;
    std::vector<Vec<D>> origin_;
    std::vector<Mat<D>> basis_;
};

}  // namespace sa
