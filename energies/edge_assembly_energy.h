#pragma once
// Edge assembly (Eq. 7): for two simplices s_i, s_j sharing a facet, the images of the facet's
// edges under A_i and A_j must agree:
//     sum_e |A_i e - A_j e|^2 = tr((A_i - A_j) M (A_i - A_j)^T),   M = sum_e e e^T,
// over the normalized edge vectors e of the shared facet (the shared edge in 2D, the three edges
// of the shared triangle in 3D). Variables: vec(A_i) then vec(A_j) (2 D^2). Quadratic.

#include <vector>

#include "optim/types.h"

namespace sa {

/// M = sum_e e e^T over the given edge vectors, each normalized to unit length.
template <int D>
Mat<D> edge_moment(const std::vector<Vec<D>>& edges);

template <int D>
class EdgeAssemblyEnergy {
public:
    static constexpr int arity = 2 * D * D;
    static constexpr bool is_quadratic = true;

    /// One moment matrix M per shared facet (edge_moment of its edges).
    explicit EdgeAssemblyEnergy(std::vector<Mat<D>> moments) : moments_(std::move(moments)) {}

    double value(Index f, const Vec<arity>& x) const {
        const Mat<D> delta = difference(x);
        return (delta * moments_[f]).cwiseProduct(delta).sum();
    }
    double value_gradient(Index f, const Vec<arity>& x, Vec<arity>& gradient) const {
        const Mat<D> delta = difference(x);
        const Mat<D> g = 2.0 * delta * moments_[f];
        gradient.template head<D * D>() = Eigen::Map<const Vec<D * D>>(g.data());
        gradient.template tail<D * D>() = -gradient.template head<D * D>();
        return 0.5 * g.cwiseProduct(delta).sum();
    }
    double value_gradient_hessian(Index f, const Vec<arity>& x, Vec<arity>& gradient,
                                  Mat<arity>& hessian) const {
        // vec(delta M) = (M kron I) vec(delta): the Hessian is 2 [[K, -K], [-K, K]].
        Mat<D * D> K;
        for (int r = 0; r < D; ++r) {
            for (int c = 0; c < D; ++c) {
                K.template block<D, D>(D * r, D * c) = 2.0 * moments_[f](r, c) * Mat<D>::Identity();
            }
        }
        hessian << K, -K, -K, K;
        return value_gradient(f, x, gradient);
    }

    const std::vector<Mat<D>>& moments() const { return moments_; }

private:
    static Mat<D> difference(const Vec<arity>& x) {
        return Eigen::Map<const Mat<D>>(x.data()) - Eigen::Map<const Mat<D>>(x.data() + D * D);
    }
    std::vector<Mat<D>> moments_;
};

template <int D>
Mat<D> edge_moment(const std::vector<Vec<D>>& edges) {
    Mat<D> m = Mat<D>::Zero();
    for (const Vec<D>& e : edges) {
        const Vec<D> u = e.normalized();
        m += u * u.transpose();
    }
    return m;
}

}  // namespace sa
