#include "frontends/hex/hex_meshing.h"

#include <cmath>
#include <sstream>

#include "frontends/hex/grid_start.h"
#include "frontends/polycube/polycube_planes.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"

namespace sa {

std::string to_string(HexOutcome outcome) {
    switch (outcome) {
        case HexOutcome::kVerified:
            return "verified";
        case HexOutcome::kPolycubeFailed:
            return "PolyCube not verified";
        case HexOutcome::kGridPolycubeFailed:
            return "PolyCube on the grid not verified";
        case HexOutcome::kHexMeshNotVerified:
            return "hex mesh not verified";
    }
    return "unknown";
}

namespace {

/// Per plane: the mean coordinate of its vertices along its axis at `positions`.
std::vector<double> plane_coordinates(const PolycubePlanes& planes,
                                      const Eigen::MatrixXd& positions) {
    std::vector<double> sum(planes.size(), 0.0);
    std::vector<Index> count(planes.size(), 0);
    for (Index v = 0; v < static_cast<Index>(planes.plane_of_vertex.size()); ++v) {
        for (int axis = 0; axis < 3; ++axis) {
            const int plane = planes.plane_of_vertex[v][axis];
            if (plane < 0) continue;
            sum[plane] += positions(v, axis);
            ++count[plane];
        }
    }
    for (int p = 0; p < planes.size(); ++p) sum[p] /= double(std::max<Index>(count[p], 1));
    return sum;
}

std::string number(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

}  // namespace

HexMeshing hex_mesh_from_polycube(const PreparedPolycube& prepared,
                                  const HexMeshingOptions& options, const Logger& logger) {
    if (!(options.padding >= 0.0) || !std::isfinite(options.padding))
        throw InvalidArgumentError("hex meshing: padding depth " + number(options.padding) +
                                   ": must be a finite number >= 0");
    if (options.hexes < 1)
        throw InvalidArgumentError("hex meshing: hexes = " + std::to_string(options.hexes) +
                                   ": must be >= 1");
    if (!(options.hex_size >= 0.0) || !std::isfinite(options.hex_size))
        throw InvalidArgumentError("hex meshing: hex size " + number(options.hex_size) +
                                   ": must be a finite number >= 0");
    HexMeshing out;
    Stopwatch clock, stage;

    // 1. The PolyCube map with free planes.
    out.polycube = solve_polycube(prepared, options.polycube, logger);
    out.polycube_seconds = stage.lap();
    if (!out.polycube.success) {
        out.outcome = HexOutcome::kPolycubeFailed;
        out.message = "no hex mesh: the PolyCube map did not verify. " + out.polycube.message;
        return out;
    }

    // 2. Its planes on the grid.
    const Eigen::MatrixXd& map = out.polycube.positions;
    const PolycubePlanes planes =
        polycube_planes(prepared.boundary, prepared.charts, prepared.mesh.num_vertices());
    const std::vector<double> coordinates = plane_coordinates(planes, map);
    std::vector<PlaneSeparation> apart;
    for (const PolycubeEdgeOrder& edge :
         polycube_edge_orders(prepared.boundary, prepared.charts, planes, prepared.mesh.vertices)) {
        const int a = edge.from_plane, b = edge.to_plane;
        if (a < 0 || b < 0 || coordinates[a] == coordinates[b]) continue;
        apart.push_back(coordinates[a] < coordinates[b] ? PlaneSeparation{a, b}
                                                        : PlaneSeparation{b, a});
    }
    const double polycube_volume = tet_mesh_volume(prepared.mesh, map);
    double cell = std::cbrt(polycube_volume / double(options.hexes));
    if (options.hex_size > 0.0) {
        // The hex size in the prepared mesh's units, then in the PolyCube's (the map changes the
        // scale by the cube root of the volume ratio).
        const double size = std::ldexp(options.hex_size, -prepared.scale_exponent);
        cell = size * std::cbrt(polycube_volume / prepared.input_volume);
    }
    out.quantization = quantize_planes(coordinates, planes.axis, apart, cell);
    const PlaneQuantization& q = out.quantization;
    const Eigen::MatrixXd start =
        grid_start(prepared.mesh.simplices, map, planes.plane_of_vertex, coordinates, q);
    std::vector<double> held(q.position.begin(), q.position.end());
    out.quantization_seconds = stage.lap();
    log_line(logger, "hex: grid of " + std::to_string(q.extent[0]) + " x " +
                         std::to_string(q.extent[1]) + " x " + std::to_string(q.extent[2]) +
                         " cells; planes per axis " + std::to_string(q.planes[0]) + ", " +
                         std::to_string(q.planes[1]) + ", " + std::to_string(q.planes[2]) + " on " +
                         std::to_string(q.distinct_positions[0]) + ", " +
                         std::to_string(q.distinct_positions[1]) + ", " +
                         std::to_string(q.distinct_positions[2]) + " grid positions; " +
                         std::to_string(apart.size()) + " PolyCube edges kept a cell long, " +
                         std::to_string(q.raised) + " planes raised past rounding");

    // 3. The PolyCube on the grid.
    PolycubeSolveOptions grid_options = options.polycube;
    grid_options.optimal_bound = false;
    grid_options.bound = options.polycube.optimal_bound ? kInfinity : options.polycube.bound;
    grid_options.max_time = std::max(options.polycube.max_time - clock.seconds(), 1e-3);
    out.grid_polycube = solve_polycube_on_planes(prepared, start, held, grid_options, logger);
    out.grid_polycube_seconds = stage.lap();
    if (!out.grid_polycube.success) {
        out.outcome = HexOutcome::kGridPolycubeFailed;
        out.message =
            "no hex mesh: the PolyCube on the grid did not verify. " + out.grid_polycube.message;
        return out;
    }

    // 4. The hexes, on the input.
    const Eigen::MatrixXd rest = prepared.rest_positions();
    out.extraction = extract_hexes(prepared.mesh.simplices, out.grid_polycube.positions, rest);
    out.extracted_quality = hex_quality(out.extraction.mesh);
    out.extraction_seconds = stage.lap();

    // 5. The padding layer, where it is needed.
    HexMesh hexes = out.extraction.mesh;
    Eigen::MatrixXd grid_points = out.extraction.grid_points.cast<double>();
    out.locked_inverted_corners = boundary_locked_inverted_corners(hexes, hex_boundary(hexes));
    if (options.padding > 0.0 && out.locked_inverted_corners > 0) {
        HexPadding padded = pad_boundary(hexes, options.padding);
        out.padding_hexes = padded.added_hexes;
        Eigen::MatrixXd padded_points(padded.mesh.num_vertices(), 3);
        for (Index v = 0; v < padded.mesh.num_vertices(); ++v)
            padded_points.row(v) = grid_points.row(padded.source[v]);
        grid_points = std::move(padded_points);
        hexes = std::move(padded.mesh);
        log_line(logger, "hex: " + std::to_string(out.locked_inverted_corners) +
                             " hex corners inverted or flat with all their vertices on the "
                             "boundary; padded with " +
                             std::to_string(out.padding_hexes) + " hexes");
    }
    out.padding_seconds = stage.lap();

    // 6. The inner vertices moved, the boundary ones slid on the surface.
    out.optimization.mesh = hexes;
    if (options.optimize) {
        const PolycubeSurface surface(prepared.boundary.triangles, out.grid_polycube.positions,
                                      rest);
        HexOptimizationOptions o;
        o.max_iterations = options.optimization_iterations;
        o.max_time = std::max(options.polycube.max_time - clock.seconds(), 1e-3);
        o.threads = options.polycube.threads;
        out.optimization = optimize_hex_mesh(hexes, o, logger, {&surface, grid_points});
    }
    out.optimization_seconds = stage.lap();

    // 7. Their checks.
    out.verification = verify_hex_mesh(out.optimization.mesh, rest, prepared.boundary.triangles,
                                       tet_mesh_volume(prepared.mesh, rest));
    out.verification_seconds = stage.lap();
    // A cell without all its corners means a map that is not injective on the grid: its hole
    // is a failure even when the rest verifies.
    const bool passed = out.verification.passed && out.extraction.cells_with_missing_corners == 0;
    out.outcome = passed ? HexOutcome::kVerified : HexOutcome::kHexMeshNotVerified;
    out.message =
        std::string(passed ? "success: hex mesh verified: " : "FAILED: hex mesh NOT verified: ") +
        out.verification.summary;
    if (out.extraction.cells_with_missing_corners > 0) {
        out.message += "; " + std::to_string(out.extraction.cells_with_missing_corners) +
                       " cells left out with a corner outside the PolyCube";
    }
    return out;
}

}  // namespace sa
