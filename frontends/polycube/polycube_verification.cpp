#include "frontends/polycube/polycube_verification.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "frontends/polycube/boundary_angle_sums.h"
#include "geometry/detail/union_find.h"
#include "optim/errors.h"

namespace sa {

namespace {

std::string number(double x) {
    std::ostringstream out;
    out.precision(3);
    out << x;
    return out.str();
}

/// The first failure of one kind, with how many there were.
struct Failure {
    Index count = 0;
    std::string first;
    void add(const std::string& what) {
        if (count++ == 0) first = what;
    }
    void report(std::vector<std::string>& failures, const char* kind) const {
        if (count == 0) return;
        failures.push_back(count == 1 ? first
                                      : first + " (and " + std::to_string(count - 1) + " more " +
                                            kind + ")");
    }
};

/// Connected runs of boundary edges between two charts: per run, its length at `positions` and
/// one of its edges.
struct EdgeRun {
    int charts[2];
    double length = 0.0;
    std::array<Index, 2> witness;
};

std::vector<EdgeRun> polycube_edge_runs(const PolycubeLayout& layout,
                                        const Eigen::MatrixXd& positions) {
    const TetBoundary& boundary = *layout.boundary;
    const PolycubeCharts& charts = *layout.charts;
    // Mesh edges between charts, keyed by their chart pair.
    std::map<std::pair<int, int>, std::vector<std::array<Index, 2>>> by_pair;
    for (Index b = 0; b < boundary.size(); ++b) {
        for (int i = 0; i < 3; ++i) {
            const Index other = boundary.adjacent[b][i];
            if (other < b) continue;  // each edge once (and not across a non-manifold edge)
            const int c0 = charts.chart_of[b], c1 = charts.chart_of[other];
            if (c0 == c1) continue;
            Index p = boundary.triangles(b, i), q = boundary.triangles(b, (i + 1) % 3);
            by_pair[{std::min(c0, c1), std::max(c0, c1)}].push_back({p, q});
        }
    }
    std::vector<EdgeRun> runs;
    UnionFind run_of(Index(positions.rows()));
    for (const auto& [pair, edges] : by_pair) {
        // Runs: components over shared vertices.
        for (const auto& e : edges) run_of.join(e[0], e[1]);
        std::map<Index, std::size_t> run_of_root;
        for (const auto& e : edges) {
            const Index root = run_of.find(e[0]);
            auto [it, inserted] = run_of_root.emplace(root, runs.size());
            if (inserted) runs.push_back({{pair.first, pair.second}, 0.0, e});
            runs[it->second].length += (positions.row(e[0]) - positions.row(e[1])).norm();
        }
        for (const auto& e : edges) run_of.reset(e[0]), run_of.reset(e[1]);
    }
    return runs;
}

}  // namespace

double tet_mesh_volume(const SimplicialMesh& mesh, const Eigen::MatrixXd& positions) {
    double volume = 0.0;
    for (Index t = 0; t < mesh.num_simplices(); ++t) {
        Eigen::Matrix3d e;
        for (int k = 0; k < 3; ++k) {
            e.col(k) =
                (positions.row(mesh.simplices(t, k + 1)) - positions.row(mesh.simplices(t, 0)))
                    .transpose();
        }
        volume += std::abs(e.determinant()) / 6.0;
    }
    return volume;
}

PolycubeVerification verify_polycube(const PolycubeLayout& layout, const Eigen::MatrixXd& positions,
                                     double input_volume, double planarity_tolerance) {
    const SimplicialMesh& mesh = *layout.mesh;
    const TetBoundary& boundary = *layout.boundary;
    const PolycubeCharts& charts = *layout.charts;
    if (positions.rows() != mesh.num_vertices() || positions.cols() != 3) {
        throw InvalidArgumentError("verify_polycube: positions must be #V x 3 = " +
                                   std::to_string(mesh.num_vertices()) + " x 3");
    }
    PolycubeVerification v;
    v.diagonal = bounding_box_diagonal(positions);
    const double tolerance = planarity_tolerance * v.diagonal;

    // Tetrahedra, and distortion at the input's volume.
    const double volume = tet_mesh_volume(mesh, positions);
    v.volume_scale = volume > 0.0 && input_volume > 0.0 ? std::cbrt(input_volume / volume) : 1.0;
    const RestFrames<3> frames = rest_frames<3>(mesh);
    v.quality =
        map_quality<3>(linear_parts<3>(mesh, frames, v.volume_scale * positions), frames.volume);
    if (v.quality.inverted > 0 || v.quality.degenerate > 0) {
        Index witness = 0;
        while (!v.quality.per_simplex[witness].inverted &&
               !v.quality.per_simplex[witness].degenerate) {
            ++witness;
        }
        v.failures.push_back(std::to_string(v.quality.inverted) + " inverted and " +
                             std::to_string(v.quality.degenerate) +
                             " degenerate tetrahedra (first: " + std::to_string(witness) + ")");
    }

    // Charts: planar, on their side.
    Failure nonplanar, wrong_side, zero_length, edge_angle, vertex_angle;
    const Eigen::MatrixXd area = boundary_area_vectors(boundary, positions);
    for (int c = 0; c < charts.size(); ++c) {
        const int axis = label_axis(charts.label[c]);
        double lo = kInfinity, hi = -kInfinity, side = 0.0;
        for (const Index b : charts.members[c]) {
            for (int i = 0; i < 3; ++i) {
                const double x = positions(boundary.triangles(b, i), axis);
                lo = std::min(lo, x);
                hi = std::max(hi, x);
            }
            side += area(b, axis) * label_sign(charts.label[c]);
        }
        v.max_planarity = std::max(v.max_planarity, (hi - lo) / v.diagonal);
        const std::string name =
            "chart " + std::to_string(c) + " (" + label_name(charts.label[c]) + ", " +
            describe_boundary_triangle(boundary, charts.members[c].front()) + ")";
        if (!(hi - lo <= tolerance)) {
            nonplanar.add(name + " is not planar: its vertices spread over " +
                          number((hi - lo) / v.diagonal) + " of the diagonal along " + "XYZ"[axis]);
        }
        if (!(side > 0.0)) {
            wrong_side.add(name + " faces away from " + label_name(charts.label[c]));
        }
    }
    nonplanar.report(v.failures, "charts");
    wrong_side.report(v.failures, "charts");
    v.nonplanar_charts = int(nonplanar.count);
    v.wrong_side_charts = int(wrong_side.count);

    // PolyCube edges.
    for (const EdgeRun& run : polycube_edge_runs(layout, positions)) {
        ++v.polycube_edges;
        v.shortest_edge = std::min(v.shortest_edge, run.length / v.diagonal);
        if (!(run.length > tolerance)) {
            zero_length.add("the PolyCube edge between charts " + std::to_string(run.charts[0]) +
                            " and " + std::to_string(run.charts[1]) + " through mesh edge (" +
                            std::to_string(run.witness[0]) + ", " + std::to_string(run.witness[1]) +
                            ") has length " + number(run.length / v.diagonal) + " of the diagonal");
        }
    }
    zero_length.report(v.failures, "PolyCube edges");
    v.zero_length_edges = int(zero_length.count);

    // Boundary angle sums.
    const std::vector<double> edge_sums = dihedral_angle_sums(*layout.fans, positions);
    for (std::size_t f = 0; f < edge_sums.size(); ++f) {
        v.max_edge_angle_sum = std::max(v.max_edge_angle_sum, edge_sums[f]);
        if (!(edge_sums[f] < 2.0 * M_PI)) {
            const auto& e = (*layout.fans)[f].edge;
            edge_angle.add("boundary edge (" + std::to_string(e[0]) + ", " + std::to_string(e[1]) +
                           ") has a dihedral-angle sum of " + number(edge_sums[f] / M_PI) + " pi");
        }
    }
    edge_angle.report(v.failures, "boundary edges");
    v.edge_angle_violations = edge_angle.count;
    const std::vector<double> vertex_sums = solid_angle_sums(*layout.stars, positions);
    for (std::size_t s = 0; s < vertex_sums.size(); ++s) {
        v.max_vertex_angle_sum = std::max(v.max_vertex_angle_sum, vertex_sums[s]);
        if (!(vertex_sums[s] < 4.0 * M_PI)) {
            vertex_angle.add("boundary vertex " + std::to_string((*layout.stars)[s].vertex) +
                             " has a solid-angle sum of " + number(vertex_sums[s] / M_PI) + " pi");
        }
    }
    vertex_angle.report(v.failures, "boundary vertices");
    v.vertex_angle_violations = vertex_angle.count;
    v.passed = v.failures.empty();
    return v;
}

}  // namespace sa
