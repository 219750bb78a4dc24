#include "frontends/hex/polycube_surface.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <vector>

#include "optim/errors.h"

namespace sa {

namespace {

constexpr double kOnPlane = 1e-6;     // grid units
constexpr double kInside = -1e-9;     // barycentric
constexpr long kBinRange = 1L << 19;  // grid coordinates within +-2^19 (hex_extraction.h)

long clamp_bin(double x) {
    return std::clamp(static_cast<long>(std::floor(x)), -kBinRange, kBinRange - 1);
}

}  // namespace

std::uint64_t PolycubeSurface::bin(int axis, long plane, long i, long j) const {
    auto field = [](long x) { return static_cast<std::uint64_t>(x + kBinRange); };  // 20 bits
    return (static_cast<std::uint64_t>(axis) << 60) | (field(plane) << 40) | (field(i) << 20) |
           field(j);
}

PolycubeSurface::PolycubeSurface(const Eigen::MatrixXi& triangles, const Eigen::MatrixXd& grid,
                                 const Eigen::MatrixXd& rest)
    : triangles_(triangles), grid_(grid), rest_(rest) {
    if (grid.rows() != rest.rows() || grid.cols() != 3 || rest.cols() != 3 || triangles.cols() != 3)
        throw InvalidArgumentError("PolycubeSurface: grid is " + std::to_string(grid.rows()) +
                                   " x " + std::to_string(grid.cols()) + ", rest " +
                                   std::to_string(rest.rows()) + " x " +
                                   std::to_string(rest.cols()) + ", triangles " +
                                   std::to_string(triangles.cols()) + " columns");
    if (triangles.size() > 0 && (triangles.minCoeff() < 0 || triangles.maxCoeff() >= grid.rows()))
        throw InvalidArgumentError("PolycubeSurface: a triangle names a vertex out of range");
    for (Index t = 0; t < triangles.rows(); ++t) {
        int axis = -1;
        for (int a = 0; a < 3; ++a) {
            double lo = kInfinity, hi = -kInfinity;
            for (int k = 0; k < 3; ++k) {
                lo = std::min(lo, grid(triangles(t, k), a));
                hi = std::max(hi, grid(triangles(t, k), a));
            }
            if (hi - lo <= kOnPlane && std::abs(lo - std::round(lo)) <= kOnPlane) axis = a;
        }
        if (axis < 0) {
            ++left_out_;
            continue;
        }
        const int b = (axis + 1) % 3, c = (axis + 2) % 3;
        const long plane = std::lround(grid(triangles(t, 0), axis));
        double lo_b = kInfinity, hi_b = -kInfinity, lo_c = kInfinity, hi_c = -kInfinity;
        for (int k = 0; k < 3; ++k) {
            lo_b = std::min(lo_b, grid(triangles(t, k), b));
            hi_b = std::max(hi_b, grid(triangles(t, k), b));
            lo_c = std::min(lo_c, grid(triangles(t, k), c));
            hi_c = std::max(hi_c, grid(triangles(t, k), c));
        }
        for (long i = clamp_bin(lo_b - kOnPlane); i <= clamp_bin(hi_b + kOnPlane); ++i)
            for (long j = clamp_bin(lo_c - kOnPlane); j <= clamp_bin(hi_c + kOnPlane); ++j)
                bins_[bin(axis, plane, i, j)].push_back(t);
    }
}

std::optional<SurfacePoint> PolycubeSurface::locate(int axis,
                                                    const Eigen::Vector3d& grid_point) const {
    if (axis < 0 || axis > 2 || !grid_point.allFinite()) return std::nullopt;
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    const long plane = std::lround(grid_point[axis]);
    const auto found =
        bins_.find(bin(axis, plane, clamp_bin(grid_point[b]), clamp_bin(grid_point[c])));
    if (found == bins_.end()) return std::nullopt;
    const Eigen::Vector2d p(grid_point[b], grid_point[c]);
    Index best = -1;
    double depth = kInside;
    Eigen::Vector3d best_weights;
    for (Index t : found->second) {
        auto in_plane = [&](int k) {
            return Eigen::Vector2d(grid_(triangles_(t, k), b), grid_(triangles_(t, k), c));
        };
        const Eigen::Vector2d g0 = in_plane(0);
        Eigen::Matrix2d M;
        M << in_plane(1) - g0, in_plane(2) - g0;
        const double det = M.determinant();
        if (!(std::abs(det) > 0.0)) continue;
        const Eigen::Vector2d l = M.inverse() * (p - g0);
        const Eigen::Vector3d w(1.0 - l[0] - l[1], l[0], l[1]);
        if (w.minCoeff() >= depth) {
            depth = w.minCoeff();
            best = t;
            best_weights = w;
        }
    }
    if (best < 0) return std::nullopt;
    return point_in(best, axis, best_weights);
}

SurfacePoint PolycubeSurface::point_in(Index t, int axis, const Eigen::Vector3d& weights) const {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    SurfacePoint out;
    out.triangle = t;
    const Eigen::Vector3d w = weights.cwiseMax(0.0) / weights.cwiseMax(0.0).sum();
    for (int k = 0; k < 3; ++k) {
        out.rest += w[k] * rest_.row(triangles_(t, k)).transpose();
        out.grid += w[k] * grid_.row(triangles_(t, k)).transpose();
    }
    auto in_plane = [&](int k) {
        return Eigen::Vector2d(grid_(triangles_(t, k), b), grid_(triangles_(t, k), c));
    };
    Eigen::Matrix2d M;
    M << in_plane(1) - in_plane(0), in_plane(2) - in_plane(0);
    Eigen::Matrix<double, 3, 2> edges;
    edges << (rest_.row(triangles_(t, 1)) - rest_.row(triangles_(t, 0))).transpose(),
        (rest_.row(triangles_(t, 2)) - rest_.row(triangles_(t, 0))).transpose();
    const Eigen::Matrix<double, 3, 2> tangent = edges * M.inverse();
    out.jacobian.col(b) = tangent.col(0);
    out.jacobian.col(c) = tangent.col(1);
    return out;
}

namespace {

/// Barycentric weights of the point of triangle (a, b, c) closest to p (Ericson, Real-Time
/// Collision Detection, 5.1.5).
Eigen::Vector3d closest_weights(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};
    const Eigen::Vector3d bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double v = d1 / (d1 - d3);
        return {1.0 - v, v, 0.0};
    }
    const Eigen::Vector3d cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double w = d2 / (d2 - d6);
        return {1.0 - w, 0.0, w};
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {0.0, 1.0 - w, w};
    }
    const double denominator = 1.0 / (va + vb + vc);
    const double v = vb * denominator, w = vc * denominator;
    return {1.0 - v - w, v, w};
}

}  // namespace

std::optional<SurfacePoint> PolycubeSurface::closest(int axis, const Eigen::Vector3d& near_grid,
                                                     const Eigen::Vector3d& rest_point,
                                                     int line_axis, double radius) const {
    if (axis < 0 || axis > 2 || line_axis > 2 || line_axis == axis || !near_grid.allFinite() ||
        !rest_point.allFinite())
        return std::nullopt;
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    const long plane = std::lround(near_grid[axis]);
    const double line = line_axis >= 0 ? std::round(near_grid[line_axis]) : 0.0;
    std::vector<Index> candidates;
    for (long i = clamp_bin(near_grid[b] - radius); i <= clamp_bin(near_grid[b] + radius); ++i) {
        for (long j = clamp_bin(near_grid[c] - radius); j <= clamp_bin(near_grid[c] + radius);
             ++j) {
            const auto found = bins_.find(bin(axis, plane, i, j));
            if (found != bins_.end())
                candidates.insert(candidates.end(), found->second.begin(), found->second.end());
        }
    }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    double best = kInfinity;
    Index best_triangle = -1;
    Eigen::Vector3d best_weights;
    for (Index t : candidates) {
        Eigen::Vector3d x[3];
        for (int k = 0; k < 3; ++k) x[k] = rest_.row(triangles_(t, k)).transpose();
        if (line_axis < 0) {
            const Eigen::Vector3d w = closest_weights(rest_point, x[0], x[1], x[2]);
            const double d = (w[0] * x[0] + w[1] * x[1] + w[2] * x[2] - rest_point).squaredNorm();
            if (d < best) {
                best = d;
                best_triangle = t;
                best_weights = w;
            }
            continue;
        }
        for (int k = 0; k < 3; ++k) {  // the sides on the line
            const int k1 = (k + 1) % 3;
            if (std::abs(grid_(triangles_(t, k), line_axis) - line) > kOnPlane ||
                std::abs(grid_(triangles_(t, k1), line_axis) - line) > kOnPlane)
                continue;
            const Eigen::Vector3d side = x[k1] - x[k];
            const double length = side.squaredNorm();
            const double u =
                length > 0.0 ? std::clamp((rest_point - x[k]).dot(side) / length, 0.0, 1.0) : 0.0;
            const double d = (x[k] + u * side - rest_point).squaredNorm();
            if (d < best) {
                best = d;
                best_triangle = t;
                best_weights.setZero();
                best_weights[k] = 1.0 - u;
                best_weights[k1] = u;
            }
        }
    }
    if (best_triangle < 0) return std::nullopt;
    return point_in(best_triangle, axis, best_weights);
}

}  // namespace sa
