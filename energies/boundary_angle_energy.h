#pragma once
// The boundary-angle barrier E_theta of section 5.1 ("Locally injective mapping"): for a boundary
// vertex v of a triangle mesh mapped to the plane,
//     E_theta(v) = 1 / (2 pi - theta_v),   theta_v = sum of the angles at v of its triangles'
//     images,
// +inf when theta_v >= 2 pi. With every triangle positively oriented, theta_v < 2 pi at every
// boundary vertex makes the map locally injective on the boundary (Lipman 2014).
//
// The K triangles around v form a fan, from the boundary edge leaving v to the one entering it;
// the angle of triangle k is arg(b_k) - arg(a_k) (atan2 of cross and dot), a_k and b_k the images
// of its two edges at v. Both edges are linear in the variables, so closed-form derivatives follow
// from those of arg(u):  d arg / du = (-u_y, u_x) / |u|^2,
//     d^2 arg / du^2 = [2 u_x u_y, u_y^2 - u_x^2; u_y^2 - u_x^2, -2 u_x u_y] / |u|^4.
//
//   BoundaryAngleEnergy<K>        variables: vec(A_k) of the K triangles (4 K), each triangle's
//                                 two edges at v given in its rest frame (r-SA and f-SA)
//   BoundaryAngleVertexEnergy<K>  variables: the positions of v and of its K + 1 fan neighbours in
//                                 order (2 K + 4) (the vertex stage)
// kMaxFan bounds K (a boundary vertex rarely has more triangles).

#include <array>
#include <cmath>
#include <vector>

#include "optim/types.h"

namespace sa {

inline constexpr int kMaxFan = 12;

/// E_theta of one boundary vertex from its angle sum: 1 / (2 pi - theta), +inf from 2 pi on.
inline double boundary_angle_barrier(double theta) {
    return theta < 2.0 * M_PI ? 1.0 / (2.0 * M_PI - theta) : kInfinity;
}

namespace detail {

/// An edge image linear in the variables: u = c0 x[i0 : i0 + 2] + c1 x[i1 : i1 + 2].
struct LinearEdge {
    std::array<int, 2> first;
    std::array<double, 2> coefficient;

    template <int N>
    Vec<2> operator()(const Vec<N>& x) const {
        return coefficient[0] * x.template segment<2>(first[0]) +
               coefficient[1] * x.template segment<2>(first[1]);
    }
};

/// theta = sum_k arg(b_k) - arg(a_k) for corners (a_k, b_k), and E = 1 / (2 pi - theta) with its
/// gradient and Hessian when g and h are given. +inf when theta >= 2 pi or an edge vanishes.
template <int N, std::size_t K>
double angle_sum_barrier(const Vec<N>& x, const std::array<std::array<LinearEdge, 2>, K>& corners,
                         Vec<N>* g, Mat<N>* h) {
    double theta = 0.0;
    for (const auto& [a_map, b_map] : corners) {
        const Vec<2> a = a_map(x), b = b_map(x);
        if (a.squaredNorm() == 0.0 || b.squaredNorm() == 0.0) return kInfinity;
        theta += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
    const double energy = boundary_angle_barrier(theta);
    if (g == nullptr || energy == kInfinity) return energy;

    // E' = E^2 and E'' = 2 E^3 with respect to theta.
    const double d1 = energy * energy, d2 = 2.0 * d1 * energy;
    Vec<N> dtheta = Vec<N>::Zero();
    h->setZero();
    for (const auto& corner : corners) {
        for (int side = 0; side < 2; ++side) {
            const LinearEdge& map = corner[side];
            const Vec<2> u = map(x);
            const double sign = side == 0 ? -1.0 : 1.0;  // theta = arg(b) - arg(a)
            const double r2 = u.squaredNorm();
            const Vec<2> du = sign * Vec<2>(-u.y(), u.x()) / r2;
            Mat<2> ddu;
            ddu << 2.0 * u.x() * u.y(), u.y() * u.y() - u.x() * u.x(),
                u.y() * u.y() - u.x() * u.x(), -2.0 * u.x() * u.y();
            ddu *= sign * d1 / (r2 * r2);
            for (int i = 0; i < 2; ++i) {
                dtheta.template segment<2>(map.first[i]) += map.coefficient[i] * du;
                for (int j = 0; j < 2; ++j) {
                    h->template block<2, 2>(map.first[i], map.first[j]) +=
                        map.coefficient[i] * map.coefficient[j] * ddu;
                }
            }
        }
    }
    *g = d1 * dtheta;
    h->noalias() += d2 * dtheta * dtheta.transpose();
    return energy;
}

}  // namespace detail

template <int K>
struct BoundaryAngleEnergy {
    static constexpr int arity = 4 * K;
    /// Per element (boundary vertex), per fan triangle: its edges at v (columns), rest frame.
    std::vector<std::array<Mat<2>, K>> edges;

    double value(Index e, const Vec<arity>& x) const {
        return detail::angle_sum_barrier<arity>(x, corners(e), nullptr, nullptr);
    }
    double value_gradient_hessian(Index e, const Vec<arity>& x, Vec<arity>& g,
                                  Mat<arity>& h) const {
        return detail::angle_sum_barrier<arity>(x, corners(e), &g, &h);
    }

  private:
    // A_k = [x0 x2; x1 x3] (column-major), so A_k e = e_0 (x0, x1) + e_1 (x2, x3).
    std::array<std::array<detail::LinearEdge, 2>, K> corners(Index e) const {
        std::array<std::array<detail::LinearEdge, 2>, K> c;
        for (int k = 0; k < K; ++k) {
            const Mat<2>& E = edges[e][k];
            for (int side = 0; side < 2; ++side) {
                c[k][side] = {{4 * k, 4 * k + 2}, {E(0, side), E(1, side)}};
            }
        }
        return c;
    }
};

template <int K>
struct BoundaryAngleVertexEnergy {
    static constexpr int arity = 2 * K + 4;

    double value(Index, const Vec<arity>& x) const {
        return detail::angle_sum_barrier<arity>(x, corners(), nullptr, nullptr);
    }
    double value_gradient_hessian(Index, const Vec<arity>& x, Vec<arity>& g, Mat<arity>& h) const {
        return detail::angle_sum_barrier<arity>(x, corners(), &g, &h);
    }

  private:
    // Triangle k has edges (p_{k+1} - v, p_{k+2} - v) with v at x[0 : 2].
    static std::array<std::array<detail::LinearEdge, 2>, K> corners() {
        std::array<std::array<detail::LinearEdge, 2>, K> c;
        for (int k = 0; k < K; ++k) {
            c[k][0] = {{2 + 2 * k, 0}, {1.0, -1.0}};
            c[k][1] = {{4 + 2 * k, 0}, {1.0, -1.0}};
        }
        return c;
    }
};

}  // namespace sa
