#include "geometry/quality/surface_distance.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "optim/errors.h"

namespace sa {

namespace {

double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                              const Eigen::Vector3d& b) {
    const Eigen::Vector3d ab = b - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return (p - (a + t * ab)).norm();
}

}  // namespace

double point_triangle_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    // The closest point by the Voronoi regions of the triangle's corners, edges and face.
    const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0) return ap.norm();
    const Eigen::Vector3d bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3) return bp.norm();
    const Eigen::Vector3d cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6) return cp.norm();
    const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    const double denominator = va + vb + vc;
    if (!(denominator > 0.0)) {  // a degenerate triangle: its closest edge
        return std::min({point_segment_distance(p, a, b), point_segment_distance(p, b, c),
                         point_segment_distance(p, c, a)});
    }
    if (vc <= 0.0 || vb <= 0.0 || va <= 0.0) {
        return std::min({point_segment_distance(p, a, b), point_segment_distance(p, b, c),
                         point_segment_distance(p, c, a)});
    }
    const double v = vb / denominator, w = vc / denominator;
    return (p - (a + v * ab + w * ac)).norm();
}

SurfaceDistance::SurfaceDistance(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& triangles)
    : vertices_(vertices), triangles_(triangles) {
    if (vertices.cols() != 3 || triangles.cols() != 3 || triangles.rows() == 0) {
        throw InvalidArgumentError(
            "SurfaceDistance: expected #V x 3 vertices and #F x 3 "
            "triangles, at least one");
    }
    if (triangles.minCoeff() < 0 || triangles.maxCoeff() >= vertices.rows())
        throw InvalidArgumentError("SurfaceDistance: a triangle index is out of range");
    const Index faces = static_cast<Index>(triangles.rows());
    Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d high = -low;
    for (Index f = 0; f < faces; ++f) {
        for (int k = 0; k < 3; ++k) {
            low = low.cwiseMin(triangle_corner(f, k));
            high = high.cwiseMax(triangle_corner(f, k));
        }
    }
    const Eigen::Vector3d extent = (high - low).cwiseMax(1e-12 * (high - low).norm() + 1e-300);
    // About one cell per triangle.
    cell_ = std::cbrt(extent.prod() / double(faces));
    cell_ = std::max(cell_, extent.maxCoeff() / 1024.0);
    origin_ = low;
    for (int k = 0; k < 3; ++k) cells_[k] = std::max(1, int(std::ceil(extent[k] / cell_)));
    const Index total = Index(cells_.prod());
    std::vector<Index> count(total + 1, 0);
    auto each_cell = [&](Index f, auto&& visit) {
        Eigen::Vector3d a = triangle_corner(f, 0), b = a;
        for (int k = 1; k < 3; ++k) {
            a = a.cwiseMin(triangle_corner(f, k));
            b = b.cwiseMax(triangle_corner(f, k));
        }
        Eigen::Vector3i lo, hi;
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::clamp(int(std::floor((a[k] - origin_[k]) / cell_)), 0, cells_[k] - 1);
            hi[k] = std::clamp(int(std::floor((b[k] - origin_[k]) / cell_)), 0, cells_[k] - 1);
        }
        for (int i = lo[0]; i <= hi[0]; ++i)
            for (int j = lo[1]; j <= hi[1]; ++j)
                for (int k = lo[2]; k <= hi[2]; ++k) visit(cell_index({i, j, k}));
    };
    for (Index f = 0; f < faces; ++f) each_cell(f, [&](Index c) { ++count[c + 1]; });
    for (Index c = 0; c < total; ++c) count[c + 1] += count[c];
    start_ = count;
    members_.resize(start_.back());
    for (Index f = 0; f < faces; ++f) each_cell(f, [&](Index c) { members_[count[c]++] = f; });
}

Eigen::Vector3d SurfaceDistance::triangle_corner(Index f, int k) const {
    return vertices_.row(triangles_(f, k)).transpose();
}

Index SurfaceDistance::cell_index(const Eigen::Vector3i& cell) const {
    return (Index(cell[0]) * cells_[1] + cell[1]) * cells_[2] + cell[2];
}

double SurfaceDistance::distance(const Eigen::Vector3d& p) const {
    Eigen::Vector3i home;
    for (int k = 0; k < 3; ++k)
        home[k] = std::clamp(int(std::floor((p[k] - origin_[k]) / cell_)), 0, cells_[k] - 1);
    // The distance from p to the grid's box, which every cell's distance includes.
    const Eigen::Vector3d box_low = origin_, box_high = origin_ + cell_ * cells_.cast<double>();
    const double outside = (p.cwiseMax(box_low).cwiseMin(box_high) - p).norm();
    double best = std::numeric_limits<double>::infinity();
    const int widest = cells_.maxCoeff();
    for (int shell = 0; shell <= widest; ++shell) {
        // Every cell of this shell is at least (shell - 1) cells from p, within the box.
        if (shell >= 1 && std::hypot(outside, (shell - 1) * cell_) >= best) break;
        for (int i = home[0] - shell; i <= home[0] + shell; ++i) {
            if (i < 0 || i >= cells_[0]) continue;
            for (int j = home[1] - shell; j <= home[1] + shell; ++j) {
                if (j < 0 || j >= cells_[1]) continue;
                for (int k = home[2] - shell; k <= home[2] + shell; ++k) {
                    if (k < 0 || k >= cells_[2]) continue;
                    const int ring = std::max(
                        {std::abs(i - home[0]), std::abs(j - home[1]), std::abs(k - home[2])});
                    if (ring != shell) continue;
                    const Index c = cell_index({i, j, k});
                    for (Index m = start_[c]; m < start_[c + 1]; ++m) {
                        const Index f = members_[m];
                        best = std::min(best, point_triangle_distance(p, triangle_corner(f, 0),
                                                                      triangle_corner(f, 1),
                                                                      triangle_corner(f, 2)));
                    }
                }
            }
        }
    }
    return best;
}

double SurfaceDistance::max_distance(const Eigen::MatrixXd& points) const {
    return tbb::parallel_reduce(
        tbb::blocked_range<Index>(0, static_cast<Index>(points.rows())), 0.0,
        [&](const tbb::blocked_range<Index>& range, double worst) {
            for (Index i = range.begin(); i != range.end(); ++i)
                worst = std::max(worst, distance(points.row(i).transpose()));
            return worst;
        },
        [](double a, double b) { return std::max(a, b); });
}

}  // namespace sa
