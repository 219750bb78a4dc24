#include "frontends/hex/hex_optimization.h"

#include <array>
#include <vector>

#include "energies/simplex_energy.h"
#include "energies/vertex_copy_energies.h"
#include "frontends/simplex_assembly/untangle.h"
#include "geometry/quality/hex_quality.h"
#include "optim/newton_solver.h"
#include "optim/point_variables.h"
#include "optim/problem.h"

namespace sa {

namespace {

/// The eight corner tetrahedra of every hex (8 #H x 4: corner, then its neighbours in positive
/// order) over the hex mesh's vertices, with the corner of a cube of edge `edge` as every rest
/// shape (the untangling energy is not blind to scale: its volume term wants det A = 1).
struct CornerTetrahedra {
    SimplicialMesh mesh;
    RestFrames<3> frames;
};

CornerTetrahedra corner_tetrahedra(const HexMesh& hexes, double edge) {
    CornerTetrahedra out;
    const Index nh = hexes.num_hexes();
    out.mesh.vertices = hexes.positions;
    out.mesh.simplices.resize(8 * nh, 4);
    for (Index h = 0; h < nh; ++h) {
        for (int c = 0; c < 8; ++c) {
            out.mesh.simplices(8 * h + c, 0) = hexes.hexes(h, c);
            for (int k = 0; k < 3; ++k)
                out.mesh.simplices(8 * h + c, k + 1) = hexes.hexes(h, kHexCornerEdges[c][k]);
        }
    }
    Eigen::Matrix<double, 3, 4> corner;
    corner << 0, edge, 0, 0, 0, 0, edge, 0, 0, 0, 0, edge;
    corner.colwise() -= corner.rowwise().mean();
    out.frames.corners.assign(8 * nh, corner);
    out.frames.edge_inverse.assign(8 * nh, Mat<3>::Identity() / edge);
    out.frames.volume.assign(8 * nh, edge * edge * edge / 6.0);
    return out;
}

}  // namespace

HexOptimization optimize_hex_mesh(const HexMesh& mesh, const HexOptimizationOptions& options,
                                  const Logger& logger) {
    HexOptimization out;
    out.mesh = mesh;
    const Index nv = mesh.num_vertices(), nh = mesh.num_hexes();
    const HexBoundary boundary = hex_boundary(mesh);
    const std::vector<unsigned char>& on_boundary = boundary.on_boundary;
    for (Index v = 0; v < nv; ++v) out.free_vertices += on_boundary[v] ? 0 : 1;
    if (out.free_vertices == 0) {
        out.message = "no vertex inside the mesh to move";
        return out;
    }
    // Inverted hexes; when all their inverted corners are locked on the boundary, nothing moves
    // them.
    Index inverted = 0, inverted_corners = 0;
    for (Index h = 0; h < nh; ++h) {
        Index bad = 0;
        for (int c = 0; c < 8; ++c) bad += hex_corner_jacobian(mesh, h, c) > 0.0 ? 0 : 1;
        inverted += bad > 0 ? 1 : 0;
        inverted_corners += bad;
    }
    if (inverted > 0 && inverted_corners == boundary_locked_inverted_corners(mesh, boundary)) {
        out.message = "not optimized: " + std::to_string(inverted) +
                      " inverted hexes, each inverted at corners with all four vertices on the "
                      "boundary";
        return out;
    }
    if (inverted > 0) {
        // The barrier is infinite on an inverted corner: untangle the corners first, each rest
        // shape a cube's corner at the mesh's mean edge length.
        double length = 0.0;
        for (Index h = 0; h < nh; ++h) {
            for (int c = 0; c < 4; ++c) {
                length += (mesh.positions.row(mesh.hexes(h, c)) -
                           mesh.positions.row(mesh.hexes(h, (c + 1) % 4)))
                              .norm();
            }
        }
        const CornerTetrahedra corners = corner_tetrahedra(mesh, length / double(4 * nh));
        UntangleOptions u;
        // To the untangling energy's convergence, not its first valid iterate, whose near-flat
        // corners would put the barrier far above where Newton can bring it down.
        u.until_valid = false;
        u.max_iterations = options.max_iterations;
        u.max_time_seconds = options.max_time;
        u.num_threads = options.threads;
        const UntangleResult r =
            untangle<3>(corners.mesh, corners.frames, mesh.positions, on_boundary, u);
        out.untangled = r.untangled;
        log_line(logger, "hex optimization: " + std::to_string(inverted) +
                             " inverted hexes; untangling their corners: " + to_string(r.outcome) +
                             " in " + std::to_string(r.iterations) + " steps");
        Index left = 0;
        HexMesh untangled = mesh;
        untangled.positions = r.positions;
        for (Index h = 0; h < nh; ++h) left += hex_min_corner_jacobian(untangled, h) > 0.0 ? 0 : 1;
        if (left > 0) {
            // Kept as it came: the untangling's last iterate may have more inverted hexes.
            out.message = "not optimized: " + std::to_string(left) + " of " +
                          std::to_string(inverted) + " inverted hexes left after untangling";
            return out;
        }
        out.mesh = untangled;
    }

    // Elements: 8 corner tetrahedra per hex, (corner, its three neighbours in positive order),
    // but those with all four vertices on the boundary: constant, they would only add their
    // value, which can dwarf the rest and end Newton's relative tests at once.
    std::vector<std::array<Index, 12>> elements;
    elements.reserve(std::size_t(8 * nh));
    for (Index h = 0; h < nh; ++h) {
        for (int c = 0; c < 8; ++c) {
            std::array<Index, 12> e;
            const std::array<int, 4> corners = {c, kHexCornerEdges[c][0], kHexCornerEdges[c][1],
                                                kHexCornerEdges[c][2]};
            bool moves = false;
            for (int k = 0; k < 4; ++k) {
                const Index v = mesh.hexes(h, corners[k]);
                moves |= !on_boundary[v];
                const auto p = point_variables<3>(v);
                for (int d = 0; d < 3; ++d) e[3 * k + d] = p[d];
            }
            if (moves) elements.push_back(e);
        }
    }
    SimplexEnergyOptions energy_options;
    energy_options.barrier_distortion = DistortionType::kConformal;
    const std::size_t corners = elements.size();
    SimplexEnergy<3> corner_energy(energy_options, std::vector<double>(corners, 1.0));
    Problem problem(flatten_points(out.mesh.positions));
    problem.add_term("hex corners, exp conformal",
                     VertexSimplexEnergy<3>(std::move(corner_energy),
                                            std::vector<Mat<3>>(corners, Mat<3>::Identity())),
                     std::move(elements));
    for (Index v = 0; v < nv; ++v)
        if (on_boundary[v]) problem.set_fixed(point_variables<3>(v));

    NewtonOptions newton;
    newton.max_iterations = options.max_iterations;
    newton.max_time_seconds = options.max_time;
    newton.num_threads = options.threads;
    newton.function_tolerance = 1e-5;
    out.newton = solve(problem, newton);
    out.ran = true;
    out.mesh.positions = unflatten_points<3>(problem.variables());
    out.message = (inverted > 0 ? std::to_string(inverted) + " inverted hexes untangled, " : "") +
                  std::to_string(out.free_vertices) + " inner vertices moved in " +
                  std::to_string(out.newton.num_steps()) + " Newton steps (" +
                  to_string(out.newton.termination) + ")";
    log_line(logger, "hex optimization: " + out.message + ", energy " +
                         std::to_string(out.newton.initial_energy) + " to " +
                         std::to_string(out.newton.final_energy) + " (" + out.newton.phase_times() +
                         ")");
    return out;
}

}  // namespace sa
