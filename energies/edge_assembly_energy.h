#pragma once
// Edge assembly (Eq. 7), in the general form that also covers Eq. 11. For two simplices s_i, s_j
// sharing a facet, the images of the facet's edges under A_i and A_j must agree:
//     sum_k |A_i e_i^k - R A_j e_j^k|^2
// over the facet's edges k (the shared edge in 2D, the three edges of the shared triangle in 3D),
// e_i^k and e_j^k being the same rest edge expressed in each simplex's rest frame and normalized
// to unit length (section 4.3: insensitive to the mesh scale). R is the identity for mappings
// (then the term is Eq. 7) and the fixed per-edge rotation R_e of a frame field for Eq. 11.
// For planar and volume meshes both frames coincide and e_i^k = e_j^k.
//
// Variables: vec(A_i) then vec(A_j), column-major (2 D^2). Quadratic: with
// r_k = A_i e_i - R A_j e_j, the Hessian is 2 [[sum e_i e_i^T (x) I, -sum e_i e_j^T (x) R],
//                                               [  (transpose),        sum e_j e_j^T (x) I]].

#include <vector>

#include "optim/types.h"

namespace sa {

template <int D>
struct SharedFacetEdges {
    static constexpr int kEdges = D == 2 ? 1 : 3;
    using Edges = Eigen::Matrix<double, D, kEdges>;
    Edges in_i;  ///< the facet's edges in s_i's rest frame, one unit column each
    Edges in_j;  ///< the same edges in s_j's rest frame
    Mat<D> rotation = Mat<D>::Identity();
};

template <int D>
class EdgeAssemblyEnergy {
  public:
    static constexpr int arity = 2 * D * D;
    static constexpr bool is_quadratic = true;
    static constexpr bool is_convex = true;  // a sum of squares of linear functions
    static constexpr int kEdges = SharedFacetEdges<D>::kEdges;

    explicit EdgeAssemblyEnergy(std::vector<SharedFacetEdges<D>> facets)
        : facets_(std::move(facets)) {}

    double value(Index f, const Vec<arity>& x) const {
        double sum = 0.0;
        const SharedFacetEdges<D>& facet = facets_[f];
        for (int k = 0; k < kEdges; ++k) sum += residual(facet, x, k).squaredNorm();
        return sum;
    }

    double value_gradient(Index f, const Vec<arity>& x, Vec<arity>& gradient) const {
        const SharedFacetEdges<D>& facet = facets_[f];
        Mat<D> gi = Mat<D>::Zero(), gj = Mat<D>::Zero();
        double sum = 0.0;
        for (int k = 0; k < kEdges; ++k) {
            const Vec<D> r = residual(facet, x, k);
            sum += r.squaredNorm();
            gi += 2.0 * r * facet.in_i.col(k).transpose();
            gj -= 2.0 * facet.rotation.transpose() * r * facet.in_j.col(k).transpose();
        }
        gradient.template head<D * D>() = Eigen::Map<const Vec<D * D>>(gi.data());
        gradient.template tail<D * D>() = Eigen::Map<const Vec<D * D>>(gj.data());
        return sum;
    }

    double value_gradient_hessian(Index f, const Vec<arity>& x, Vec<arity>& gradient,
                                  Mat<arity>& hessian) const {
        const SharedFacetEdges<D>& facet = facets_[f];
        const Mat<D> Mii = facet.in_i * facet.in_i.transpose();
        const Mat<D> Mij = facet.in_i * facet.in_j.transpose();
        const Mat<D> Mjj = facet.in_j * facet.in_j.transpose();
        const Mat<D> I = Mat<D>::Identity();
        // (P kron Q) has block (r, c) = P(r, c) Q.
        for (int r = 0; r < D; ++r) {
            for (int c = 0; c < D; ++c) {
                hessian.template block<D, D>(D * r, D * c) = 2.0 * Mii(r, c) * I;
                hessian.template block<D, D>(D * D + D * r, D * D + D * c) = 2.0 * Mjj(r, c) * I;
                const Mat<D> off = -2.0 * Mij(r, c) * facet.rotation;
                hessian.template block<D, D>(D * r, D * D + D * c) = off;
                hessian.template block<D, D>(D * D + D * c, D * r) = off.transpose();
            }
        }
        return value_gradient(f, x, gradient);
    }

    const std::vector<SharedFacetEdges<D>>& facets() const { return facets_; }

  private:
    static Vec<D> residual(const SharedFacetEdges<D>& facet, const Vec<arity>& x, int k) {
        const Eigen::Map<const Mat<D>> Ai(x.data()), Aj(x.data() + D * D);
        return Ai * facet.in_i.col(k) - facet.rotation * (Aj * facet.in_j.col(k));
    }
    std::vector<SharedFacetEdges<D>> facets_;
};

}  // namespace sa
