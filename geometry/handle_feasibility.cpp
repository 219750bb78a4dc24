#include "geometry/handle_feasibility.h"

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
    if (parts.empty()) return "the handles allow a solution";
    std::string text;
    for (const std::string& part : parts) text += (text.empty() ? "" : "; ") + part;
    return text;
}

HandleFeasibility check_handle_feasibility(const SimplicialMesh& mesh,
                                           const std::vector<Index>& handles,
                                           const Eigen::MatrixXd& targets, double tolerance) {
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
    return result;
}

InfeasibleProblemError::InfeasibleProblemError(const std::string& source,
                                               HandleFeasibility diagnosis)
    : Error(source + ": infeasible as posed, no optimization run: " + diagnosis.describe()),
      diagnosis_(std::move(diagnosis)) {}

}  // namespace sa
