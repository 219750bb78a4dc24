#include "energies/boundary_angle_energy.h"

#include <array>
#include <cmath>

namespace sa {

namespace {

/// An edge image linear in the variables: u = c0 x[i0 : i0 + 2] + c1 x[i1 : i1 + 2].
struct LinearEdge {
    std::array<int, 2> first;
    std::array<double, 2> coefficient;

    Vec<2> operator()(const ConstVectorRef& x) const {
        return coefficient[0] * x.segment<2>(first[0]) + coefficient[1] * x.segment<2>(first[1]);
    }
};
using Corner = std::array<LinearEdge, 2>;

/// theta = sum_k arg(b_k) - arg(a_k) over the K corners (a_k, b_k) = corner(k), and
/// E = 1 / (2 pi - theta) with its gradient and Hessian when g and h are given. +inf when
/// theta >= 2 pi or an edge vanishes.
template <class Corners>
double angle_sum_barrier(const ConstVectorRef& x, int K, const Corners& corner, VectorRef* g,
                         MatrixRef* h) {
    double theta = 0.0;
    for (int k = 0; k < K; ++k) {
        const auto [a_map, b_map] = corner(k);
        const Vec<2> a = a_map(x), b = b_map(x);
        if (a.squaredNorm() == 0.0 || b.squaredNorm() == 0.0) return kInfinity;
        theta += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
    const double energy = boundary_angle_barrier(theta);
    if (g == nullptr || energy == kInfinity) return energy;

    // E' = E^2 and E'' = 2 E^3 with respect to theta; g holds d theta until the end.
    const double d1 = energy * energy, d2 = 2.0 * d1 * energy;
    VectorRef& dtheta = *g;
    dtheta.setZero();
    h->setZero();
    for (int k = 0; k < K; ++k) {
        const Corner c = corner(k);
        for (int side = 0; side < 2; ++side) {
            const LinearEdge& map = c[side];
            const Vec<2> u = map(x);
            const double sign = side == 0 ? -1.0 : 1.0;  // theta = arg(b) - arg(a)
            const double r2 = u.squaredNorm();
            const Vec<2> du = sign * Vec<2>(-u.y(), u.x()) / r2;
            Mat<2> ddu;
            ddu << 2.0 * u.x() * u.y(), u.y() * u.y() - u.x() * u.x(),
                u.y() * u.y() - u.x() * u.x(), -2.0 * u.x() * u.y();
            ddu *= sign * d1 / (r2 * r2);
            for (int i = 0; i < 2; ++i) {
                dtheta.segment<2>(map.first[i]) += map.coefficient[i] * du;
                for (int j = 0; j < 2; ++j) {
                    h->block<2, 2>(map.first[i], map.first[j]) +=
                        map.coefficient[i] * map.coefficient[j] * ddu;
                }
            }
        }
    }
    h->noalias() += d2 * dtheta * dtheta.transpose();
    dtheta *= d1;
    return energy;
}

// A_k = [x0 x2; x1 x3] (column-major), so A_k e = e_0 (x0, x1) + e_1 (x2, x3).
auto linear_corners(const std::vector<Mat<2>>& edges) {
    return [&edges](int k) {
        const Mat<2>& E = edges[k];
        Corner c;
        for (int side = 0; side < 2; ++side)
            c[side] = {{4 * k, 4 * k + 2}, {E(0, side), E(1, side)}};
        return c;
    };
}

// Triangle k has edges (p_{k+1} - v, p_{k+2} - v) with v at x[0 : 2].
Corner vertex_corner(int k) {
    return {LinearEdge{{2 + 2 * k, 0}, {1.0, -1.0}}, LinearEdge{{4 + 2 * k, 0}, {1.0, -1.0}}};
}

int vertex_fan_size(const ConstVectorRef& x) {
    return static_cast<int>(x.size() - 4) / 2;
}

}  // namespace

double BoundaryAngleEnergy::value(Index e, ConstVectorRef x) const {
    return angle_sum_barrier(x, int(edges[e].size()), linear_corners(edges[e]), nullptr, nullptr);
}

double BoundaryAngleEnergy::value_gradient_hessian(Index e, ConstVectorRef x, VectorRef g,
                                                   MatrixRef h) const {
    return angle_sum_barrier(x, int(edges[e].size()), linear_corners(edges[e]), &g, &h);
}

double BoundaryAngleVertexEnergy::value(Index, ConstVectorRef x) const {
    return angle_sum_barrier(x, vertex_fan_size(x), vertex_corner, nullptr, nullptr);
}

double BoundaryAngleVertexEnergy::value_gradient_hessian(Index, ConstVectorRef x, VectorRef g,
                                                         MatrixRef h) const {
    return angle_sum_barrier(x, vertex_fan_size(x), vertex_corner, &g, &h);
}

}  // namespace sa
