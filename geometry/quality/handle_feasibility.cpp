#include "geometry/quality/handle_feasibility.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <sstream>

namespace sa {

namespace {

/// Signed volume (times d!) of the simplex whose corners are the columns of `corners`
/// (d x (d + 1)).
double signed_volume(const Eigen::MatrixXd& corners) {
    const Index d = corners.rows();
    Eigen::MatrixXd edges(d, d);
    for (Index k = 0; k < d; ++k) edges.col(k) = corners.col(k + 1) - corners.col(0);
    return edges.determinant();
}

/// The rest orientation of simplex s: the sign of its volume when the rest shape has as many
/// coordinates as the simplex has dimensions, +1 for triangles in space (their own frame).
/// `rest` is the mesh's vertices scaled by power_of_two_scale().
double rest_orientation(const SimplicialMesh& mesh, const Eigen::MatrixXd& rest, Index s) {
    const int d = mesh.simplex_dimension();
    if (mesh.ambient_dimension() != d) return 1.0;
    Eigen::MatrixXd corners(d, d + 1);
    for (int k = 0; k <= d; ++k) corners.col(k) = rest.row(mesh.simplices(s, k)).transpose();
    return signed_volume(corners) < 0.0 ? -1.0 : 1.0;
}

/// The power of two that brings the largest coefficient of `m` near 1 (1 for an empty, zero or
/// non-finite `m`): the volumes and distances below neither overflow nor underflow at any scale
/// (a mesh at 1e200 had every fixed simplex "flat" and every edge "collapsed"), and the scaling
/// is exact.
double power_of_two_scale(const Eigen::MatrixXd& m) {
    const double largest = m.size() > 0 ? m.cwiseAbs().maxCoeff() : 0.0;
    if (!(largest > 0.0) || !std::isfinite(largest)) return 1.0;
    return std::ldexp(1.0, -std::ilogb(largest));
}

template <class List, class Print>
std::string listed(const List& list, std::size_t shown, Print print) {
    std::ostringstream out;
    for (std::size_t k = 0; k < std::min(shown, list.size()); ++k) {
        if (k) out << ", ";
        print(out, list[k]);
    }
    if (list.size() > shown) out << ", ...";
    return out.str();
}

/// The fixed-boundary check (handle_feasibility.h) on every part whose boundary vertices are all
/// handles; returns the parts that fail it. `row_of[v]` is v's row of `scaled` (-1: not a handle).
std::vector<FixedBoundaryPart> failing_fixed_boundaries(const SimplicialMesh& mesh,
                                                        const MeshTopology& topology,
                                                        const std::vector<Index>& row_of,
                                                        const Eigen::MatrixXd& scaled,
                                                        const Eigen::MatrixXd& rest, double scale) {
    std::vector<FixedBoundaryPart> failing;
    const int d = mesh.simplex_dimension();
    Index count = 0;
    const std::vector<Index> part = topology.simplex_components(&count);
    std::vector<unsigned char> fixed(count, 1), bounded(count, 0);
    for (const BoundaryFacet& f : topology.boundary_facets) {
        bounded[part[f.simplex]] = 1;
        for (int k = 0; k < d; ++k)
            if (row_of[f.vertices[k]] < 0) fixed[part[f.simplex]] = 0;
    }
    std::vector<std::vector<Index>> simplices(count), facets(count);
    for (Index c = 0; c < count; ++c) fixed[c] = fixed[c] && bounded[c];
    for (Index s = 0; s < mesh.num_simplices(); ++s)
        if (fixed[part[s]]) simplices[part[s]].push_back(s);
    for (std::size_t f = 0; f < topology.boundary_facets.size(); ++f)
        if (fixed[part[topology.boundary_facets[f].simplex]])
            facets[part[topology.boundary_facets[f].simplex]].push_back(Index(f));

    double factorial = 1.0;
    for (int k = 2; k <= d; ++k) factorial *= k;
    Eigen::MatrixXd corners(d, d + 1);
    // Per vertex, for the loops of one part at a time (reset after each part: a mesh may have
    // many small parts).
    std::vector<Index> next(mesh.num_vertices(), -1);
    std::vector<unsigned char> seen(mesh.num_vertices(), 0), used(mesh.num_vertices(), 0);
    for (Index c = 0; c < count; ++c) {
        if (!fixed[c]) continue;
        const BoundaryFacet& first = topology.boundary_facets[facets[c].front()];
        const Eigen::VectorXd origin = scaled.row(row_of[first.vertices[0]]).transpose();
        // The enclosed volume as the sum of the cones from `origin` to the boundary facets, each
        // oriented as its simplex's facet; and as the sum over the simplices with every interior
        // vertex at `origin`: the two agree when the orientations are consistent (they always are
        // for a valid rest shape), which is what makes the volume independent of the interior.
        double cones = 0.0, magnitude = 0.0, collapsed = 0.0;
        for (Index f : facets[c]) {
            const BoundaryFacet& b = topology.boundary_facets[f];
            for (int k = 0; k <= d; ++k) {
                const Index v = mesh.simplices(b.simplex, k);
                corners.col(k) = k == b.opposite ? origin : Eigen::VectorXd(scaled.row(row_of[v]));
            }
            const double cone = rest_orientation(mesh, rest, b.simplex) * signed_volume(corners);
            cones += cone;
            magnitude += std::abs(cone);
        }
        for (Index s : simplices[c]) {
            for (int k = 0; k <= d; ++k) {
                const Index v = mesh.simplices(s, k);
                corners.col(k) = row_of[v] < 0 ? origin : Eigen::VectorXd(scaled.row(row_of[v]));
            }
            collapsed += rest_orientation(mesh, rest, s) * signed_volume(corners);
        }
        if (!(std::abs(cones - collapsed) <= 1e-9 * magnitude)) continue;  // not decided
        FixedBoundaryPart p;
        p.dimension = d;
        p.simplices = Index(simplices[c].size());
        p.first_simplex = simplices[c].front();
        p.volume = cones / factorial / std::pow(scale, d);
        p.encloses_volume = cones > 1e-12 * magnitude;
        bool fails = !p.encloses_volume;

        if (d == 2 && scaled.cols() == 2) {
            // The boundary loops, each edge directed with its triangle's rest orientation.
            bool loops = true;
            for (Index f : facets[c]) {
                const BoundaryFacet& b = topology.boundary_facets[f];
                Index from = mesh.simplices(b.simplex, (b.opposite + 1) % 3);
                Index to = mesh.simplices(b.simplex, (b.opposite + 2) % 3);
                if (rest_orientation(mesh, rest, b.simplex) < 0.0) std::swap(from, to);
                loops = loops && next[from] < 0;
                next[from] = to;
            }
            double turning = 0.0;
            for (Index f : facets[c]) {
                if (!loops) break;
                const Index start = topology.boundary_facets[f].vertices[0];
                if (seen[start]) continue;
                Index v = start;
                do {
                    seen[v] = 1;
                    const Index u = next[v], w = u >= 0 ? next[u] : -1;
                    if (w < 0) {
                        loops = false;
                        break;
                    }
                    const Eigen::Vector2d a =
                        (scaled.row(row_of[u]) - scaled.row(row_of[v])).transpose();
                    const Eigen::Vector2d e =
                        (scaled.row(row_of[w]) - scaled.row(row_of[u])).transpose();
                    if (a.squaredNorm() == 0.0 || e.squaredNorm() == 0.0) loops = false;
                    turning += std::atan2(a.x() * e.y() - a.y() * e.x(), a.dot(e));
                    v = u;
                } while (loops && v != start);
            }
            if (loops) {
                Index vertices = 0;
                for (Index s : simplices[c])
                    for (int k = 0; k < 3; ++k)
                        if (!used[mesh.simplices(s, k)]) {
                            used[mesh.simplices(s, k)] = 1;
                            ++vertices;
                        }
                const Index edges = (3 * p.simplices + Index(facets[c].size())) / 2;
                p.turning_measured = true;
                p.turning = int(std::lround(turning / (2.0 * M_PI)));
                p.euler = vertices - edges + p.simplices;
                fails = fails || p.turning < p.euler;
            }
            for (Index f : facets[c]) {
                for (int k = 0; k < 2; ++k) {
                    next[topology.boundary_facets[f].vertices[k]] = -1;
                    seen[topology.boundary_facets[f].vertices[k]] = 0;
                }
            }
            for (Index s : simplices[c])
                for (int k = 0; k < 3; ++k) used[mesh.simplices(s, k)] = 0;
        }
        if (fails) failing.push_back(p);
    }
    return failing;
}

}  // namespace

std::string HandleFeasibility::describe(std::size_t shown) const {
    auto index = [](std::ostream& out, Index i) { out << i; };
    std::vector<std::string> parts;
    if (!inverted.empty() || !flat.empty()) {
        std::ostringstream out;
        out << "of the " << fixed_simplices << " simplices whose vertices are all handles, ";
        if (!inverted.empty())
            out << inverted.size() << " are inverted (" << listed(inverted, shown, index) << ")";
        if (!inverted.empty() && !flat.empty()) out << " and ";
        if (!flat.empty()) out << flat.size() << " are flat (" << listed(flat, shown, index) << ")";
        parts.push_back(out.str());
    }
    if (!conflicts.empty()) {
        parts.push_back(
            std::to_string(conflicts.size()) +
            " handles are fixed twice at different places (vertices " +
            listed(conflicts, shown,
                   [](std::ostream& out, const HandleConflict& c) { out << c.vertex; }) +
            ")");
    }
    if (!collapsed_edges.empty()) {
        parts.push_back(std::to_string(collapsed_edges.size()) +
                        " rest edges have both ends at one target (edges " +
                        listed(collapsed_edges, shown,
                               [](std::ostream& out, const std::array<Index, 2>& e) {
                                   out << e[0] << "-" << e[1];
                               }) +
                        ")");
    }
    for (const FixedBoundaryPart& p : enclosing) {
        std::ostringstream out;
        out << "the " << p.simplices << " simplices connected to simplex " << p.first_simplex
            << " have every boundary vertex a handle, and ";
        if (!p.encloses_volume) {
            out << "their boundary's image encloses a signed "
                << (p.dimension == 2 ? "area" : "volume") << " of " << p.volume
                << " (their images' " << (p.dimension == 2 ? "areas" : "volumes")
                << " sum to it: it must be positive)";
        } else {
            out << "their boundary loops turn " << p.turning
                << " times in all, fewer than their Euler "
                << "characteristic " << p.euler << " (a disk's boundary must turn once)";
        }
        parts.push_back(out.str());
    }
    if (parts.empty()) return "the handles allow a solution";
    std::string text;
    for (const std::string& part : parts) text += (text.empty() ? "" : "; ") + part;
    return text;
}

HandleFeasibility check_handle_feasibility(const SimplicialMesh& mesh,
                                           const std::vector<Index>& handles,
                                           const Eigen::MatrixXd& targets, double tolerance,
                                           const MeshTopology* topology) {
    HandleFeasibility result;
    const int d = mesh.simplex_dimension();
    if (handles.empty()) return result;
    const double scale = power_of_two_scale(targets.leftCols(d));
    const Eigen::MatrixXd scaled = targets.leftCols(d) * scale;
    const Eigen::MatrixXd rest = mesh.vertices * power_of_two_scale(mesh.vertices);
    // The first target of every handle vertex (its row, -1 for other vertices); repeated entries
    // are compared with it. An array, not a map: every simplex looks its vertices up.
    std::vector<Index> row_of(mesh.num_vertices(), -1);
    for (std::size_t k = 0; k < handles.size(); ++k) {
        Index& first = row_of[handles[k]];
        if (first < 0) {
            first = Index(k);
            continue;
        }
        const Eigen::RowVectorXd a = targets.row(first).head(d), b = targets.row(k).head(d);
        if ((scaled.row(first) - scaled.row(k)).norm() > tolerance * scale)
            result.conflicts.push_back({handles[k], a, b});
    }

    // Fixed simplices: signed volumes of their images against the rest orientation.
    std::vector<Index> fixed;
    std::vector<double> volume;
    Eigen::MatrixXd corners(d, d + 1);
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        bool all = true;
        for (int k = 0; k <= d && all; ++k) all = row_of[mesh.simplices(s, k)] >= 0;
        if (!all) continue;
        for (int k = 0; k <= d; ++k)
            corners.col(k) = scaled.row(row_of[mesh.simplices(s, k)]).transpose();
        fixed.push_back(s);
        volume.push_back(rest_orientation(mesh, rest, s) * signed_volume(corners));
    }
    result.fixed_simplices = static_cast<Index>(fixed.size());
    double largest = 0.0;
    for (double v : volume) largest = std::max(largest, std::abs(v));
    for (std::size_t k = 0; k < fixed.size(); ++k) {
        if (!(std::abs(volume[k]) > 1e-14 * largest)) {
            result.flat.push_back(fixed[k]);
        } else if (volume[k] < 0.0) {
            result.inverted.push_back(fixed[k]);
        }
    }

    // Rest edges between handles that share a target.
    Eigen::RowVectorXd low = scaled.colwise().minCoeff();
    Eigen::RowVectorXd high = scaled.colwise().maxCoeff();
    const double zero = 1e-14 * (high - low).norm();
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        for (int a = 0; a <= d; ++a) {
            for (int b = a + 1; b <= d; ++b) {
                Index u = mesh.simplices(s, a), v = mesh.simplices(s, b);
                if (u > v) std::swap(u, v);
                if (row_of[u] < 0 || row_of[v] < 0) continue;
                if ((scaled.row(row_of[u]) - scaled.row(row_of[v])).norm() <= zero)
                    result.collapsed_edges.push_back({u, v});
            }
        }
    }
    std::sort(result.collapsed_edges.begin(), result.collapsed_edges.end());
    result.collapsed_edges.erase(
        std::unique(result.collapsed_edges.begin(), result.collapsed_edges.end()),
        result.collapsed_edges.end());
    // The fixed boundaries, once the simplices and edges are known to be sound (a collapsed edge
    // or a flat fixed simplex would be counted again as a boundary enclosing nothing).
    if (topology != nullptr && result.feasible())
        result.enclosing = failing_fixed_boundaries(mesh, *topology, row_of, scaled, rest, scale);
    return result;
}

InfeasibleProblemError::InfeasibleProblemError(const std::string& source,
                                               HandleFeasibility diagnosis)
    : NoSolutionError(source +
                      ": infeasible as posed, no optimization run: " + diagnosis.describe()),
      diagnosis_(std::move(diagnosis)) {}

}  // namespace sa
