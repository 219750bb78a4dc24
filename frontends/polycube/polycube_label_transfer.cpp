#include "frontends/polycube/polycube_label_transfer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include "frontends/polycube/polycube_labeling.h"
#include "optim/errors.h"

namespace sa {

namespace {

/// Boundary vertices hashed on a grid of cell `h`: the nearest one within h of a point.
class VertexGrid {
  public:
    VertexGrid(const Eigen::MatrixXd& points, const std::vector<Index>& ids, double h)
        : points_(points), h_(h) {
        for (const Index v : ids) cells_[key(cell_of(points.row(v).transpose()))].push_back(v);
    }
    /// The nearest vertex within h of p, or -1.
    Index nearest(const Eigen::Vector3d& p) const {
        const Eigen::Vector3i c = cell_of(p);
        Index best = -1;
        double best_distance = h_;
        for (int dx = -1; dx <= 1; ++dx) {
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto it = cells_.find(key(c + Eigen::Vector3i(dx, dy, dz)));
                    if (it == cells_.end()) continue;
                    for (const Index v : it->second) {
                        const double d = (points_.row(v).transpose() - p).norm();
                        if (d <= best_distance) {
                            best_distance = d;
                            best = v;
                        }
                    }
                }
            }
        }
        return best;
    }

  private:
    Eigen::Vector3i cell_of(const Eigen::Vector3d& p) const {
        return (p / h_).array().floor().cast<int>();
    }
    static std::uint64_t key(const Eigen::Vector3i& c) {
        const auto u = [](int x) { return std::uint64_t(std::uint32_t(x)) & 0x1FFFFF; };
        return (u(c.x()) << 42) | (u(c.y()) << 21) | u(c.z());
    }
    const Eigen::MatrixXd& points_;
    double h_;
    std::unordered_map<std::uint64_t, std::vector<Index>> cells_;
};

std::array<Index, 3> sorted(Index a, Index b, Index c) {
    std::array<Index, 3> t{a, b, c};
    std::sort(t.begin(), t.end());
    return t;
}

}  // namespace

std::vector<int> transfer_surface_labels(const SimplicialMesh& mesh, const TetBoundary& boundary,
                                         const SimplicialMesh& surface,
                                         const std::vector<int>& surface_labels,
                                         const std::string& source, double tolerance) {
    if (surface.simplices.cols() != 3 || surface.vertices.cols() != 3) {
        throw InputError(source + ": the labelled surface must be triangles in space");
    }
    if (static_cast<Index>(surface_labels.size()) != surface.num_simplices()) {
        throw InputError(source + ": " + std::to_string(surface_labels.size()) + " labels for " +
                         std::to_string(surface.num_simplices()) + " triangles");
    }
    if (!(tolerance > 0.0 && tolerance <= 0.25)) {
        throw InvalidArgumentError("transfer_surface_labels: tolerance must be in (0, 0.25]");
    }
    // Each boundary vertex's shortest boundary edge: the scale its match is measured against.
    std::vector<double> local(mesh.num_vertices(), kInfinity);
    double longest = 0.0;
    for (const auto& e : boundary.edges) {
        const double length = (mesh.vertices.row(e[0]) - mesh.vertices.row(e[1])).norm();
        local[e[0]] = std::min(local[e[0]], length);
        local[e[1]] = std::min(local[e[1]], length);
        longest = std::max(longest, length);
    }
    std::vector<Index> boundary_vertices;
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        if (boundary.on_boundary[v]) boundary_vertices.push_back(v);
    }
    // A match is at most tolerance * longest away: one cell of the grid.
    const VertexGrid grid(mesh.vertices, boundary_vertices, tolerance * longest);
    std::vector<Index> match(surface.num_vertices(), -1);
    std::unordered_map<Index, Index> matched_by;
    std::vector<unsigned char> used(surface.num_vertices(), 0);
    for (Index f = 0; f < surface.num_simplices(); ++f) {
        for (int k = 0; k < 3; ++k) used[surface.simplices(f, k)] = 1;
    }
    for (Index v = 0; v < surface.num_vertices(); ++v) {
        if (!used[v]) continue;
        const Eigen::Vector3d p = surface.vertices.row(v).transpose();
        const Index m = grid.nearest(p);
        if (m < 0 || (mesh.vertices.row(m).transpose() - p).norm() > tolerance * local[m]) {
            throw InputError(source + ": surface vertex " + std::to_string(v) +
                             " is not at a boundary vertex of the tetrahedral mesh (none within " +
                             std::to_string(tolerance) + " of the vertex's shortest edge)");
        }
        const auto [it, inserted] = matched_by.emplace(m, v);
        if (!inserted) {
            throw InputError(source + ": surface vertices " + std::to_string(it->second) + " and " +
                             std::to_string(v) + " are both at boundary vertex " +
                             std::to_string(m));
        }
        match[v] = m;
    }
    std::map<std::array<Index, 3>, Index> boundary_of;
    for (Index b = 0; b < boundary.size(); ++b) {
        boundary_of.emplace(
            sorted(boundary.triangles(b, 0), boundary.triangles(b, 1), boundary.triangles(b, 2)),
            b);
    }
    std::vector<int> labels(boundary.size(), kNoLabel);
    for (Index f = 0; f < surface.num_simplices(); ++f) {
        const auto it =
            boundary_of.find(sorted(match[surface.simplices(f, 0)], match[surface.simplices(f, 1)],
                                    match[surface.simplices(f, 2)]));
        if (it == boundary_of.end()) {
            throw InputError(source + ": surface triangle " + std::to_string(f) +
                             " is not a boundary triangle of the tetrahedral mesh");
        }
        if (labels[it->second] != kNoLabel) {
            throw InputError(source + ": surface triangle " + std::to_string(f) +
                             " repeats the boundary triangle of " +
                             describe_boundary_triangle(boundary, it->second));
        }
        labels[it->second] = surface_labels[f];
    }
    for (Index b = 0; b < boundary.size(); ++b) {
        if (labels[b] == kNoLabel) {
            throw InputError(source + ": the surface has no triangle at the boundary triangle of " +
                             describe_boundary_triangle(boundary, b));
        }
    }
    return labels;
}

}  // namespace sa
