#include "frontends/polycube/polycube_preparation.h"

#include <sstream>

#include "geometry/io/mesh_file.h"
#include "geometry/io/polycube_labels_io.h"
#include "geometry/polycube_label_transfer.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"

namespace sa {

namespace {

std::vector<int> read_labels(const SimplicialMesh& mesh, const std::string& source,
                             const TetBoundary& boundary, const PolycubeLabelInput& input,
                             PreparedPolycube& p, const Logger& logger) {
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
        const SimplicialMesh surface = read_mesh_file(input.surface).mesh;
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
    p.label_source = "computed";
    std::vector<int> labels = closest_axis_labels(boundary, mesh.vertices);
    const LabelCleanupReport cleanup =
        clean_polycube_labels(boundary, mesh.vertices, labels, input.cleanup);
    p.cleanup = cleanup;
    std::ostringstream line;
    line << source << ": labels by closest axis, " << cleanup.charts_before << " charts; clean-up "
         << cleanup.charts_after << " charts, " << cleanup.triangles_changed
         << " triangles relabelled (" << cleanup.merged_small << " small, "
         << cleanup.merged_few_neighbours << " with few neighbours, " << cleanup.merged_opposite
         << " beside their opposite; " << cleanup.teeth << " teeth)";
    log_line(logger, line.str());
    if (!cleanup.clean) {
        throw InputError(source + ": the computed labelling could not be cleaned in " +
                         std::to_string(cleanup.rounds) + " rounds; give one with --labels");
    }
    return labels;
}

}  // namespace

std::vector<int> PreparedPolycube::output_flags() const {
    return facet_flags(boundary, mesh.num_simplices(), labels, output_sign);
}

PreparedPolycube prepare_polycube(const SimplicialMesh& mesh, const std::string& source,
                                  const PolycubeLabelInput& input, const Logger& logger) {
    if (mesh.simplex_dimension() != 3 || mesh.ambient_dimension() != 3) {
        throw InputError(source + ": a PolyCube map needs a tetrahedral mesh");
    }
    validate_mesh(mesh, source);
    PreparedPolycube p;
    p.input = mesh;
    Stopwatch stage;
    const MeshTopology topology = mesh_topology(mesh, source);
    const TetBoundary boundary = tet_boundary(mesh, topology);
    std::vector<int> labels = read_labels(mesh, source, boundary, input, p, logger);
    validate_polycube_labels(mesh, boundary, labels,
                             p.label_source == "computed" ? source : p.label_source);
    p.non_monotone = non_monotone_boundaries(boundary, mesh.vertices, labels,
                                             polycube_charts(boundary, mesh.vertices, labels));
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

    p.mesh = mesh;
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
    return p;
}

}  // namespace sa
