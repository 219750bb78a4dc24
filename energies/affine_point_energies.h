#pragma once
// Assembly terms on the image of a rest point under a simplex's affine map x -> A u + T, where u
// is the point in the simplex's rest frame relative to the frame's origin (its centroid).
//
//   AffinePointAgreementEnergy   |(A_p u_p + T_p) - (A_q u_q + T_q)|^2
//       two simplices agree on a shared vertex: the vertex assembly of Eq. 9 (r-SA) and the
//       edge-endpoint constraints of Eq. 2 (f-SA). Variables vec(A_p), T_p, vec(A_q), T_q.
//   AffinePointTargetEnergy      |A_p u_p + T_p - v*|^2
//       a handle reaches its target: Eq. 8 (r-SA) and Eq. 3 (f-SA). Variables vec(A_p), T_p.
//
// Both are quadratic. With G(u) = [u^T (x) I, I] (D x (D^2 + D)) the image is G(u) (vec A, T).

#include <vector>

#include "optim/types.h"

namespace sa {

namespace detail {
/// Hessian block 2 G(u)^T G(w) of the map (vec A, T) -> A u + T, scaled by `sign`.
template <int D>
Mat<D * D + D> affine_point_gram(const Vec<D>& u, const Vec<D>& w) {
    constexpr int M = D * D + D;
    Eigen::Matrix<double, D, M> Gu, Gw;
    for (int c = 0; c < D; ++c) {
        Gu.template block<D, D>(0, D * c) = u[c] * Mat<D>::Identity();
        Gw.template block<D, D>(0, D * c) = w[c] * Mat<D>::Identity();
    }
    Gu.template rightCols<D>() = Mat<D>::Identity();
    Gw.template rightCols<D>() = Mat<D>::Identity();
    return 2.0 * Gu.transpose() * Gw;
}

template <int D>
Vec<D> affine_image(const double* x, const Vec<D>& u) {
    return Eigen::Map<const Mat<D>>(x) * u + Eigen::Map<const Vec<D>>(x + D * D);
}

/// Gradient of |r|^2 with respect to (vec A, T) when the image A u + T enters r with `sign`.
template <int D>
void add_affine_point_gradient(const Vec<D>& r, const Vec<D>& u, double sign, double* g) {
    for (int c = 0; c < D; ++c) Eigen::Map<Vec<D>>(g + D * c) += 2.0 * sign * u[c] * r;
    Eigen::Map<Vec<D>>(g + D * D) += 2.0 * sign * r;
}
}  // namespace detail

template <int D>
class AffinePointAgreementEnergy {
  public:
    static constexpr int kBlock = D * D + D;
    static constexpr int arity = 2 * kBlock;
    static constexpr bool is_quadratic = true;
    static constexpr bool is_convex = true;  // a sum of squares of linear functions

    struct Point {
        Vec<D> in_p;  ///< the shared point in s_p's rest frame
        Vec<D> in_q;  ///< the same point in s_q's rest frame
    };
    explicit AffinePointAgreementEnergy(std::vector<Point> points) : points_(std::move(points)) {}

    double value(Index i, const Vec<arity>& x) const { return residual(i, x).squaredNorm(); }
    double value_gradient(Index i, const Vec<arity>& x, Vec<arity>& g) const {
        const Vec<D> r = residual(i, x);
        g.setZero();
        detail::add_affine_point_gradient<D>(r, points_[i].in_p, 1.0, g.data());
        detail::add_affine_point_gradient<D>(r, points_[i].in_q, -1.0, g.data() + kBlock);
        return r.squaredNorm();
    }
    double value_gradient_hessian(Index i, const Vec<arity>& x, Vec<arity>& g,
                                  Mat<arity>& h) const {
        const Point& p = points_[i];
        h.template topLeftCorner<kBlock, kBlock>() = detail::affine_point_gram<D>(p.in_p, p.in_p);
        h.template bottomRightCorner<kBlock, kBlock>() =
            detail::affine_point_gram<D>(p.in_q, p.in_q);
        h.template topRightCorner<kBlock, kBlock>() = -detail::affine_point_gram<D>(p.in_p, p.in_q);
        h.template bottomLeftCorner<kBlock, kBlock>() =
            -detail::affine_point_gram<D>(p.in_q, p.in_p);
        return value_gradient(i, x, g);
    }

  private:
    Vec<D> residual(Index i, const Vec<arity>& x) const {
        return detail::affine_image<D>(x.data(), points_[i].in_p) -
               detail::affine_image<D>(x.data() + kBlock, points_[i].in_q);
    }
    std::vector<Point> points_;
};

template <int D>
class AffinePointTargetEnergy {
  public:
    static constexpr int arity = D * D + D;
    static constexpr bool is_quadratic = true;
    static constexpr bool is_convex = true;  // a sum of squares of linear functions

    struct Target {
        Vec<D> point;   ///< u: the handle in the simplex's rest frame
        Vec<D> target;  ///< v*: where its image must go
    };
    explicit AffinePointTargetEnergy(std::vector<Target> targets) : targets_(std::move(targets)) {}

    double value(Index i, const Vec<arity>& x) const { return residual(i, x).squaredNorm(); }
    double value_gradient(Index i, const Vec<arity>& x, Vec<arity>& g) const {
        const Vec<D> r = residual(i, x);
        g.setZero();
        detail::add_affine_point_gradient<D>(r, targets_[i].point, 1.0, g.data());
        return r.squaredNorm();
    }
    double value_gradient_hessian(Index i, const Vec<arity>& x, Vec<arity>& g,
                                  Mat<arity>& h) const {
        h = detail::affine_point_gram<D>(targets_[i].point, targets_[i].point);
        return value_gradient(i, x, g);
    }

  private:
    Vec<D> residual(Index i, const Vec<arity>& x) const {
        return detail::affine_image<D>(x.data(), targets_[i].point) - targets_[i].target;
    }
    std::vector<Target> targets_;
};

}  // namespace sa
