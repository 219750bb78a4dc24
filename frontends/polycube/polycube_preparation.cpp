#include "frontends/polycube/polycube_preparation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "frontends/polycube/polycube_label_transfer.h"
#include "geometry/io/mesh_file.h"
#include "geometry/io/polycube_labels_io.h"
#include "geometry/mesh/mesh_topology.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"

namespace sa {

namespace {

/// Labels from a .flags file, or from per-triangle labels of a boundary surface.
std::vector<int> read_file_labels(const SimplicialMesh& mesh, const TetBoundary& boundary,
                                  const PolycubeLabelInput& input, PreparedPolycube& p,
                                  const Logger& logger) {
    if (!input.flags.empty()) {
        p.label_source = input.flags;
        const std::vector<int> flags = read_facet_flags(input.flags, mesh.num_simplices());
        LabelConvention convention;
        std::vector<int> labels = labels_from_file_axes(
            mesh, boundary,
            boundary_labels_from_flags(boundary, mesh.num_simplices(), flags, input.flags),
            input.flags, &convention);
        p.convention = convention;
        if (convention.outward == 0 && convention.inward > 0) p.output_sign = FlagSign::kInward;
        log_line(logger, input.flags + ": " + convention.describe());
        return labels;
    }
    if (!input.labels.empty() || !input.surface.empty()) {
        if (input.labels.empty() || input.surface.empty()) {
            throw InvalidArgumentError(
                "per-triangle labels need both the labels and the surface they refer to");
        }
        p.label_source = input.labels;
        // In the mesh's units (PreparedPolycube::scale_exponent), as its positions are.
        SimplicialMesh surface = read_mesh_file(input.surface).mesh;
        surface.vertices *= std::ldexp(1.0, -p.scale_exponent);
        const std::vector<int> surface_labels =
            read_triangle_labels(input.labels, surface.num_simplices());
        const std::vector<int> file_labels =
            transfer_surface_labels(mesh, boundary, surface, surface_labels, input.surface);
        LabelConvention convention;
        std::vector<int> labels =
            labels_from_file_axes(mesh, boundary, file_labels, input.labels, &convention);
        p.convention = convention;
        if (convention.outward == 0 && convention.inward > 0) p.output_sign = FlagSign::kInward;
        log_line(logger, input.labels + ": " + convention.describe());
        return labels;
    }
    throw InvalidArgumentError("read_file_labels: no label file");
}

/// Closest-axis labels of the mesh turned by `rotation`, cleaned, and what makes them usable.
struct OrientedLabelling {
    PolycubeOrientation orientation;
    SimplicialMesh oriented;  ///< the input with its vertices turned: R x
    std::vector<int> labels;
    LabelCleanupReport cleanup;
    std::string error;  ///< why they cannot be used (empty: they can)
    std::vector<NonMonotoneBoundary> turning;
    std::optional<LabelRepairReport> repair;
};

OrientedLabelling labelling_in(const SimplicialMesh& mesh, const std::string& source,
                               const TetBoundary& boundary, const PolycubeOrientation& orientation,
                               const PolycubeLabelInput& input) {
    const LabelCleanupOptions& options = input.cleanup;
    OrientedLabelling l;
    l.orientation = orientation;
    l.oriented = mesh;
    l.oriented.vertices = mesh.vertices * orientation.rotation.transpose();
    l.labels = closest_axis_labels(boundary, l.oriented.vertices);
    l.cleanup = clean_polycube_labels(boundary, l.oriented.vertices, l.labels, options);
    if (!l.cleanup.clean) {
        l.error = source + ": the computed labelling could not be cleaned in " +
                  std::to_string(l.cleanup.rounds) + " rounds; give one with --labels";
        return l;
    }
    try {
        validate_polycube_labels(l.oriented, boundary, l.labels, source);
    } catch (const InputError& e) {
        l.error = e.what();
        return l;
    }
    l.turning = non_monotone_boundaries(boundary, l.oriented.vertices, l.labels,
                                        polycube_charts(boundary, l.oriented.vertices, l.labels));
    if (!l.turning.empty() && input.repair) {
        LabelRepairOptions repair;
        repair.cleanup = options;
        l.repair = repair_turning_boundaries(boundary, l.oriented.vertices, l.labels, repair);
        l.turning =
            non_monotone_boundaries(boundary, l.oriented.vertices, l.labels,
                                    polycube_charts(boundary, l.oriented.vertices, l.labels));
    }
    return l;
}

/// Strongly backward edges of the closest-axis labels, before any repair.
Index backward_before_repair(const OrientedLabelling& l) {
    if (l.repair) return l.repair->backward_before;
    Index backward = 0;
    for (const NonMonotoneBoundary& t : l.turning) backward += t.strongly_backward;
    return backward;
}

/// Whether labelling `b` is to be preferred to `a`: usable where `a` is not, else fewer chart
/// boundaries that turn back, else fewer strongly backward edges before the repair (labels that
/// needed less relabelling follow the shape better: on cup the cube cover of the other folds
/// several times more, docs/measurements.md), else a better l1 alignment (polycube_orientation.h).
bool preferred(const OrientedLabelling& b, const OrientedLabelling& a) {
    if (a.error.empty() != b.error.empty()) return b.error.empty();
    if (b.turning.size() != a.turning.size()) return b.turning.size() < a.turning.size();
    const Index backward_a = backward_before_repair(a), backward_b = backward_before_repair(b);
    if (backward_a != backward_b) return backward_b < backward_a;
    return b.orientation.energy < a.orientation.energy * (1.0 - 1e-9);
}

void log_labelling(const OrientedLabelling& l, const std::string& source, const Logger& logger) {
    const LabelCleanupReport& cleanup = l.cleanup;
    std::ostringstream line;
    line << source << ": labels by closest axis, " << cleanup.charts_before << " charts; clean-up "
         << cleanup.charts_after << " charts, " << cleanup.triangles_changed
         << " triangles relabelled (" << cleanup.merged_small << " small, "
         << cleanup.merged_few_neighbours << " with few neighbours, " << cleanup.merged_opposite
         << " beside their opposite; " << cleanup.teeth << " teeth)";
    log_line(logger, line.str());
    if (l.repair) {
        const LabelRepairReport& r = *l.repair;
        log_line(logger,
                 source + ": repair of boundaries turning back: " +
                     std::to_string(r.turning_before) + " -> " + std::to_string(r.turning_after) +
                     " boundaries, " + std::to_string(r.backward_before) + " -> " +
                     std::to_string(r.backward_after) + " strongly backward edges; " +
                     std::to_string(r.moves) + " moves, " + std::to_string(r.triangles_changed) +
                     " triangles relabelled (" + std::to_string(r.trials) + " labellings tried)");
    }
}

/// Throws InputError when the boundary is not a closed manifold surface: an edge with other than
/// two boundary triangles. Charts, their planes and the angle sums need one; a mesh whose
/// neighbouring tetrahedra split their common face differently (non-conforming: they share the
/// face's vertices, not its triangles) has such edges all through its inside.
void require_manifold_boundary(const TetBoundary& boundary, const std::string& source) {
    std::map<std::array<Index, 2>, int> count;
    for (Index b = 0; b < boundary.size(); ++b) {
        for (int i = 0; i < 3; ++i) {
            if (boundary.adjacent[b][i] >= 0) continue;
            Index p = boundary.triangles(b, i), q = boundary.triangles(b, (i + 1) % 3);
            ++count[{std::min(p, q), std::max(p, q)}];
        }
    }
    if (count.empty()) return;
    const auto& [edge, triangles] = *count.begin();
    throw InputError(
        source +
        ": the boundary is not a closed manifold surface: " + std::to_string(count.size()) +
        " edges have other than two boundary triangles, e.g. (" + std::to_string(edge[0]) + ", " +
        std::to_string(edge[1]) + ") with " + std::to_string(triangles) +
        " (0-based vertices); a non-conforming mesh, whose neighbouring tetrahedra "
        "split a common face differently, looks like this. A PolyCube map needs a "
        "conforming tetrahedral mesh with a manifold boundary");
}

/// Throws InputError when the splits left tetrahedra flat on the planes (PolycubeSplitReport::
/// flat_tets): no map with planar charts can be valid, so the solve would run to its time limit
/// and fail. Names the first by its vertices and each vertex's charts (the usual cause: two
/// charts of one axis that meet at a vertex only, which puts them in one plane).
void require_no_flat_tets(const PreparedPolycube& p, Index input_vertices,
                          const std::string& source) {
    if (p.splits.flat_tets.empty()) return;
    std::vector<std::vector<int>> charts(p.mesh.num_vertices());  // per vertex, sorted
    for (Index b = 0; b < p.boundary.size(); ++b) {
        for (int i = 0; i < 3; ++i)
            charts[p.boundary.triangles(b, i)].push_back(p.charts.chart_of[b]);
    }
    for (auto& of : charts) {
        std::sort(of.begin(), of.end());
        of.erase(std::unique(of.begin(), of.end()), of.end());
    }
    auto chart_name = [&](int c) {
        return label_name(p.charts.label[c]) + " chart " + std::to_string(c);
    };
    const Index t = p.splits.flat_tets.front();
    std::string where;
    std::vector<int> seen;  // the tetrahedron's charts
    for (int k = 0; k < 4; ++k) {
        const Index v = p.mesh.simplices(t, k);
        where += (k == 0 ? "" : "; ") + std::string("vertex ") + std::to_string(v) +
                 (v >= input_vertices ? " (added by a split)" : "");
        if (charts[v].empty()) where += " inside";
        for (std::size_t i = 0; i < charts[v].size(); ++i) {
            where += (i == 0 ? " on " : ", ") + chart_name(charts[v][i]);
            seen.push_back(charts[v][i]);
        }
    }
    // Where two of its charts of one axis meet.
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    for (std::size_t i = 0; i < seen.size(); ++i) {
        for (std::size_t j = i + 1; j < seen.size(); ++j) {
            if (label_axis(p.charts.label[seen[i]]) != label_axis(p.charts.label[seen[j]]))
                continue;
            for (Index v = 0; v < p.mesh.num_vertices(); ++v) {
                const auto& of = charts[v];
                if (std::binary_search(of.begin(), of.end(), seen[i]) &&
                    std::binary_search(of.begin(), of.end(), seen[j])) {
                    where += "; " + chart_name(seen[i]) + " and " + chart_name(seen[j]) +
                             " meet at vertex " + std::to_string(v);
                    break;
                }
            }
        }
    }
    const bool computed = p.label_source == "computed";
    throw InputError(
        (computed ? source : p.label_source) + ": the " + (computed ? "computed " : "") +
        "labels admit no valid PolyCube map: " + std::to_string(p.splits.flat_tets.size()) +
        " tetrahedra are flat wherever the planes go (charts of one axis that share a vertex lie "
        "in one plane) and no split repairs them, e.g. the one with " +
        where + " (0-based vertices)" +
        (computed ? "; give labels of your own with --labels" : ""));
}

}  // namespace

Eigen::MatrixXd PreparedPolycube::rest_positions() const {
    // Rows are turned as x R^T; the input's own vertices are copied, not turned back.
    Eigen::MatrixXd x =
        in_input_units(orientation ? mesh.vertices * orientation->rotation : mesh.vertices);
    x.topRows(input.num_vertices()) = input.vertices;
    return x;
}

Eigen::MatrixXd PreparedPolycube::in_input_units(const Eigen::MatrixXd& positions) const {
    return positions * std::ldexp(1.0, scale_exponent);
}

std::vector<int> PreparedPolycube::output_flags() const {
    return facet_flags(boundary, mesh.num_simplices(), labels, output_sign);
}

PreparedPolycube prepare_polycube(const SimplicialMesh& given, const std::string& source,
                                  const PolycubeLabelInput& input, const Logger& logger) {
    if (given.simplex_dimension() != 3 || given.ambient_dimension() != 3) {
        throw InputError(source + ": a PolyCube map needs a tetrahedral mesh");
    }
    validate_mesh(given, source);
    PreparedPolycube p;
    p.input = given;
    // Everything from here on at unit scale: a mesh at 1e100 or 1e-100 is prepared and solved as
    // at 1 (its areas and volumes would overflow or underflow), with the same bits.
    p.scale_exponent = scale_exponent(given.vertices);
    SimplicialMesh mesh = given;
    mesh.vertices *= std::ldexp(1.0, -p.scale_exponent);
    Stopwatch stage;
    const MeshTopology topology = mesh_topology(mesh, source);
    const TetBoundary boundary = tet_boundary(mesh, topology);
    require_manifold_boundary(boundary, source);
    SimplicialMesh surface;
    surface.vertices = mesh.vertices;
    surface.simplices = boundary.triangles;
    require_no_pinched_vertex(surface, mesh_topology(surface, source), source,
                              "a PolyCube map needs a boundary that is a closed manifold surface");
    SimplicialMesh oriented = mesh;
    std::vector<int> labels;
    if (input.flags.empty() && input.labels.empty() && input.surface.empty()) {
        // Computed labels: in the input's axes and in the orientation whose boundary faces the
        // axes best, the better of the two labellings (preferred()).
        p.label_source = "computed";
        OrientedLabelling chosen =
            labelling_in(mesh, source, boundary, PolycubeOrientation{}, input);
        chosen.orientation.energy = chosen.orientation.energy_identity = l1_alignment(
            boundary_area_vectors(boundary, mesh.vertices), Eigen::Matrix3d::Identity());
        if (input.orient) {
            const PolycubeOrientation best = polycube_orientation(boundary, mesh.vertices);
            if (best.angle_degrees > 0.0) {
                OrientedLabelling turned = labelling_in(mesh, source, boundary, best, input);
                auto usable = [](const OrientedLabelling& l) {
                    if (!l.error.empty()) return std::string("unusable");
                    std::string s = std::to_string(l.turning.size()) + " turning back";
                    if (l.repair) {
                        s += " (" + std::to_string(l.repair->turning_before) + " with " +
                             std::to_string(l.repair->backward_before) +
                             " strongly backward edges before the repair)";
                    }
                    return s;
                };
                char line[480];
                std::snprintf(line, sizeof line,
                              "%s: orientation: turned by %.2f degrees the boundary faces the "
                              "axes best (l1 alignment %.4f, %.4f as given; 1 = every triangle "
                              "faces an axis); labels there: %s, as given: %s",
                              source.c_str(), best.angle_degrees, best.energy, best.energy_identity,
                              usable(turned).c_str(), usable(chosen).c_str());
                log_line(logger, line);
                if (preferred(turned, chosen)) chosen = std::move(turned);
            }
        }
        log_labelling(chosen, source, logger);
        if (!chosen.error.empty()) throw InputError(chosen.error);
        p.orientation = chosen.orientation;
        p.cleanup = chosen.cleanup;
        p.repair = chosen.repair;
        p.non_monotone = chosen.turning;
        labels = std::move(chosen.labels);
        oriented = std::move(chosen.oriented);
    } else {
        labels = read_file_labels(mesh, boundary, input, p, logger);
        validate_polycube_labels(mesh, boundary, labels, p.label_source);
        p.non_monotone = non_monotone_boundaries(boundary, mesh.vertices, labels,
                                                 polycube_charts(boundary, mesh.vertices, labels));
    }
    if (!p.non_monotone.empty()) {
        const NonMonotoneBoundary& worst = p.non_monotone.front();
        log_line(logger,
                 (p.label_source == "computed" ? source : p.label_source) + ": " +
                     std::to_string(p.non_monotone.size()) +
                     " chart boundaries turn back along their PolyCube edge (the longest "
                     "reversal: " +
                     label_name(worst.label_a) + " | " + label_name(worst.label_b) + ", " +
                     std::to_string(worst.strongly_backward) + " of its " +
                     std::to_string(worst.edges) + " edges, at vertex " +
                     std::to_string(worst.vertex) +
                     ", 0-based); the map must fold or flatten tetrahedra there unless the mesh "
                     "makes room");
    }
    p.read_labels_seconds = stage.lap();

    p.mesh = oriented;
    p.facet_labels = facet_flags(boundary, mesh.num_simplices(), labels);
    p.splits = split_squashed_elements(p.mesh, p.facet_labels, source);
    p.topology = mesh_topology(p.mesh, source);
    p.boundary = tet_boundary(p.mesh, p.topology);
    p.labels =
        boundary_labels_from_flags(p.boundary, p.mesh.num_simplices(), p.facet_labels, source);
    p.charts = polycube_charts(p.boundary, p.mesh.vertices, p.labels);
    p.fans = boundary_edge_fans(p.mesh, p.topology, p.boundary);
    p.stars = boundary_vertex_stars(p.mesh, p.topology, p.boundary);
    p.input_volume = tet_mesh_volume(mesh, mesh.vertices);
    p.angle_bound = polycube_angle_bound(p.boundary, p.charts, p.mesh.vertices);
    p.splits_seconds = stage.lap();
    const SquashedElements& before = p.splits.before;
    log_line(logger, source + ": " + std::to_string(p.charts.size()) +
                         " charts; squashed: " + std::to_string(before.tets) + " tetrahedra, " +
                         std::to_string(before.interior_edges) + " interior edges, " +
                         std::to_string(before.boundary_edges) + " boundary edges, " +
                         std::to_string(before.boundary_triangles) + " boundary triangles, " +
                         std::to_string(before.flattened_tets) +
                         " other tetrahedra flat on the planes; " +
                         std::to_string(p.splits.edge_splits) + " edge and " +
                         std::to_string(p.splits.face_splits) + " face splits" +
                         (p.splits.after.total() > 0
                              ? "; " + std::to_string(p.splits.after.flattened_tets) +
                                    " tetrahedra flat on the planes remain (no split repairs them)"
                              : std::string()));
    require_no_flat_tets(p, mesh.num_vertices(), source);
    if (p.angle_bound.bound > 1.0 + 1e-9) {
        char bound[32];
        std::snprintf(bound, sizeof bound, "%.4g", p.angle_bound.bound);
        log_line(logger, (p.label_source == "computed" ? source : p.label_source) +
                             ": every valid PolyCube map of these labels has conformal distortion "
                             ">= " +
                             bound + ": " + p.angle_bound.worst.front().describe() +
                             " (polycube_angle_bound.h)");
    }
    return p;
}

}  // namespace sa
