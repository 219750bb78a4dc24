#include "frontends/hex/hex_optimization.h"

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "energies/exponent_continuation.h"
#include "energies/simplex_energy.h"
#include "energies/subspace_point_energy.h"
#include "energies/vertex_copy_energies.h"
#include "frontends/simplex_assembly/untangle.h"
#include "geometry/quality/hex_quality.h"
#include "optim/errors.h"
#include "optim/newton_solver.h"
#include "optim/point_variables.h"
#include "optim/problem.h"
#include "optim/stopwatch.h"

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

/// Newton steps per round: the boundary's tangent planes are redrawn after each round.
constexpr int kStepsPerRound = 20;
constexpr double kRoundDecrease = 1e-4;
constexpr double kSmallestRoundStep = 1.0 / 64.0;
/// Cells around a moved grid point where its closest rest point is looked for.
constexpr double kSearchRadius = 2.0;
/// The exponent s of exp(s d) for a round at `positions`: continuation_exponent() of 1 and the
/// corners' spread of conformal distortions (energies/exponent_continuation.h). A corner left
/// nearly flat by the untangling (d in the hundreds) would take hundreds of Newton steps at s = 1
/// (Newton lowers exp(s d)'s d by about 1/s per step) and its value would swamp the sum; the
/// rounds raise s to 1 as the spread falls.
double exponent_scale(const Eigen::MatrixXd& positions,
                      const std::vector<std::array<Index, 4>>& corners) {
    SimplexEnergyOptions o;
    o.barrier_distortion = DistortionType::kConformal;
    const SimplexEnergy<3> measure(o, {});
    double worst = 1.0, best = kInfinity;
    for (const auto& c : corners) {
        Mat<3> edges;
        for (int k = 0; k < 3; ++k)
            edges.col(k) = (positions.row(c[k + 1]) - positions.row(c[0])).transpose();
        const double d = measure.barrier_distortion(edges);
        worst = std::max(worst, d);
        best = std::min(best, d);
    }
    return continuation_exponent(1.0, worst - std::min(best, worst));
}

/// What a vertex may do: move freely (inner), slide (on plane `plane`, along the grid axes
/// `along`, -1 for none), or nothing.
struct Motion {
    enum Kind { kInner, kSliding, kFixed } kind = kInner;
    int plane = -1;
    std::array<int, 2> along = {-1, -1};
    int line = -1;  ///< on a PolyCube edge: the axis of its second plane
};

/// Per vertex, from the axes of its boundary quads at their grid points: one axis a, sliding
/// in the plane x_a (along the two other axes); two, along the third axis (located on the first
/// plane); three, or no surface, fixed.
std::vector<Motion> vertex_motions(const HexMesh& mesh, const HexBoundary& boundary,
                                   const HexBoundarySurface& surface) {
    const Index nv = mesh.num_vertices();
    std::vector<Motion> motion(nv);
    std::vector<int> axes(nv, 0);  // bit a: a boundary quad of the vertex lies on a plane x_a
    for (Eigen::Index f = 0; f < boundary.quads.rows(); ++f) {
        int plane = -1;
        if (surface.surface != nullptr) {
            for (int a = 0; a < 3; ++a) {
                double lo = kInfinity, hi = -kInfinity;
                for (int k = 0; k < 4; ++k) {
                    lo = std::min(lo, surface.grid_points(boundary.quads(f, k), a));
                    hi = std::max(hi, surface.grid_points(boundary.quads(f, k), a));
                }
                if (hi - lo < 0.5) plane = a;
            }
        }
        for (int k = 0; k < 4; ++k) axes[boundary.quads(f, k)] |= plane >= 0 ? 1 << plane : 8;
    }
    for (Index v = 0; v < nv; ++v) {
        if (!boundary.on_boundary[v]) continue;
        Motion& m = motion[v];
        m.kind = Motion::kFixed;
        const int bits = axes[v];
        if (bits >= 8 || bits == 0) continue;
        const int count = (bits & 1) + ((bits >> 1) & 1) + ((bits >> 2) & 1);
        if (count == 3) continue;
        m.kind = Motion::kSliding;
        m.plane = (bits & 1) ? 0 : (bits & 2) ? 1 : 2;
        if (count == 1) {
            m.along = {(m.plane + 1) % 3, (m.plane + 2) % 3};
        } else {
            for (int a = 0; a < 3; ++a) {
                if (!(bits & (1 << a))) m.along[0] = a;
                if ((bits & (1 << a)) && a != m.plane) m.line = a;
            }
        }
    }
    return motion;
}

}  // namespace

HexOptimization optimize_hex_mesh(const HexMesh& mesh, const HexOptimizationOptions& options,
                                  const Logger& logger, const HexBoundarySurface& surface) {
    if (surface.surface != nullptr &&
        (surface.grid_points.rows() != mesh.num_vertices() || surface.grid_points.cols() != 3))
        throw InvalidArgumentError("optimize_hex_mesh: " + std::to_string(mesh.num_vertices()) +
                                   " vertices but grid points " +
                                   std::to_string(surface.grid_points.rows()) + " x " +
                                   std::to_string(surface.grid_points.cols()));
    HexOptimization out;
    out.mesh = mesh;
    const Index nv = mesh.num_vertices(), nh = mesh.num_hexes();
    const HexBoundary boundary = hex_boundary(mesh);
    const std::vector<unsigned char>& on_boundary = boundary.on_boundary;
    const std::vector<Motion> motion = vertex_motions(mesh, boundary, surface);
    for (Index v = 0; v < nv; ++v) {
        out.free_vertices += motion[v].kind == Motion::kInner ? 1 : 0;
        out.sliding_vertices += motion[v].kind == Motion::kSliding ? 1 : 0;
    }
    if (out.free_vertices + out.sliding_vertices == 0) {
        out.message = "no vertex to move";
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

    // The corner tetrahedra that move.
    std::vector<std::array<Index, 4>> elements;
    elements.reserve(std::size_t(8 * nh));
    for (Index h = 0; h < nh; ++h) {
        for (int c = 0; c < 8; ++c) {
            std::array<Index, 4> e = {mesh.hexes(h, c), mesh.hexes(h, kHexCornerEdges[c][0]),
                                      mesh.hexes(h, kHexCornerEdges[c][1]),
                                      mesh.hexes(h, kHexCornerEdges[c][2])};
            bool moves = false;
            for (Index v : e) moves |= motion[v].kind != Motion::kFixed;
            if (moves) elements.push_back(e);
        }
    }
    // exp(s d) per corner, s chosen each round (exponent_scale()).
    const auto corner_energy = [&](double s) {
        SimplexEnergyOptions o;
        o.barrier_distortion = DistortionType::kConformal;
        o.barrier.s = s;
        const std::size_t n = elements.size();
        return VertexSimplexEnergy<3>(SimplexEnergy<3>(o, std::vector<double>(n, 1.0)),
                                      std::vector<Mat<3>>(n, Mat<3>::Identity()));
    };
    std::vector<std::array<Index, 12>> position_elements;
    position_elements.reserve(elements.size());
    for (const auto& e : elements) {
        std::array<Index, 12> x;
        for (int k = 0; k < 4; ++k)
            for (int d = 0; d < 3; ++d) x[3 * k + d] = point_variables<3>(e[k])[d];
        position_elements.push_back(x);
    }

    NewtonOptions newton;
    newton.num_threads = options.threads;
    newton.function_tolerance = 1e-5;
    const Stopwatch clock;
    const Index n = out.mesh.num_vertices();
    Eigen::MatrixXd grid = surface.grid_points;
    bool converged = false;
    while (!converged && out.newton_steps < options.max_iterations &&
           clock.seconds() < options.max_time) {
        ++out.rounds;
        const double s = exponent_scale(out.mesh.positions, elements);
        // E(positions) at this round's s, for its step.
        Problem measure(flatten_points(out.mesh.positions));
        measure.add_term("hex corners", corner_energy(s), position_elements);
        const double energy = measure.value();

        // Each vertex's position as origin + basis q: q the position itself inside, the
        // displacement of its PolyCube point in grid units on the boundary.
        std::vector<Vec<3>> origins(n, Vec<3>::Zero());
        std::vector<Mat<3>> bases(n, Mat<3>::Identity());
        Eigen::MatrixXd q = out.mesh.positions;
        for (Index v = 0; v < n; ++v) {
            if (motion[v].kind == Motion::kInner) continue;
            origins[v] = out.mesh.positions.row(v).transpose();
            bases[v].setZero();
            q.row(v).setZero();
            if (motion[v].kind == Motion::kFixed) continue;
            const std::optional<SurfacePoint> at =
                surface.surface->locate(motion[v].plane, grid.row(v).transpose());
            if (!at) continue;  // then it stays (a point location that failed at the start)
            for (int k = 0; k < 2; ++k)
                if (motion[v].along[k] >= 0) bases[v].col(k) = at->jacobian.col(motion[v].along[k]);
        }
        Problem problem(flatten_points(q));
        problem.add_term("hex corners, exp conformal",
                         SubspacePointEnergy<4, 3, VertexSimplexEnergy<3>>(
                             corner_energy(s), elements, origins, bases),
                         position_elements);
        for (Index v = 0; v < n; ++v)
            for (int d = 0; d < 3; ++d)
                if (motion[v].kind != Motion::kInner && bases[v].col(d).isZero())
                    problem.set_fixed(point_variables<3>(v)[d]);
        newton.max_time_seconds = std::max(options.max_time - clock.seconds(), 1e-3);
        newton.max_iterations =
            std::min<int>(kStepsPerRound, options.max_iterations - int(out.newton_steps));
        out.newton = solve(problem, newton);
        out.newton_steps += out.newton.num_steps();
        const Eigen::MatrixXd step = unflatten_points<3>(problem.variables()) - q;

        // The step, its boundary part brought back to the surface, halved until it is valid and
        // lower.
        bool accepted = false;
        for (double alpha = 1.0; alpha >= kSmallestRoundStep && !accepted; alpha *= 0.5) {
            Eigen::MatrixXd positions = out.mesh.positions;
            Eigen::MatrixXd moved_grid = grid;
            for (Index v = 0; v < n; ++v) {
                if (motion[v].kind == Motion::kInner) {
                    positions.row(v) += alpha * step.row(v);
                } else if (motion[v].kind == Motion::kSliding && !step.row(v).isZero()) {
                    // On the tangent plane (line), then back to the surface: the closest point
                    // of the rest surface near where the grid point went.
                    Eigen::Vector3d near = grid.row(v).transpose();
                    for (int k = 0; k < 2; ++k)
                        if (motion[v].along[k] >= 0) near[motion[v].along[k]] += alpha * step(v, k);
                    const Eigen::Vector3d tangent =
                        origins[v] + alpha * bases[v] * step.row(v).transpose();
                    const std::optional<SurfacePoint> at = surface.surface->closest(
                        motion[v].plane, near, tangent, motion[v].line, kSearchRadius);
                    if (!at) continue;  // stays where it was
                    positions.row(v) = at->rest.transpose();
                    moved_grid.row(v) = at->grid.transpose();
                }
            }
            const double e = measure.value(flatten_points(positions));
            if (!(e < energy)) continue;
            accepted = true;
            out.mesh.positions = positions;
            grid = moved_grid;
            converged = s == 1.0 && energy - e < kRoundDecrease * energy;
        }
        if (!accepted) break;
    }
    out.ran = true;
    out.message = (inverted > 0 ? std::to_string(inverted) + " inverted hexes untangled, " : "") +
                  std::to_string(out.free_vertices) + " inner vertices moved" +
                  (out.sliding_vertices > 0
                       ? " and " + std::to_string(out.sliding_vertices) + " boundary vertices slid"
                       : "") +
                  " in " + std::to_string(out.rounds) + " rounds of " +
                  std::to_string(out.newton_steps) + " Newton steps";
    log_line(logger, "hex optimization: " + out.message);
    return out;
}

}  // namespace sa
