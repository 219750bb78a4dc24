#include "frontends/simplex_assembly/vertex_stage.h"

#include <cstdio>

#include "energies/boundary_angle_energy.h"
#include "energies/vertex_copy_energies.h"
#include "optim/newton_solver.h"
#include "optim/problem.h"

namespace sa {

template <int D>
VertexStage run_vertex_stage(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                             const SimplexEnergy<D>& energy, const Eigen::MatrixXd& start,
                             const std::vector<unsigned char>& fixed,
                             const SimplexAssemblyOptions& options, const Logger& logger,
                             const std::vector<BoundaryFan>& fans) {
    VertexStage result;
    result.positions = start;
    const Index nv = mesh.num_vertices();
    // Variables: vertex-major coordinates, x[D v + c].
    Eigen::VectorXd x(static_cast<Index>(D) * nv);
    for (Index v = 0; v < nv; ++v) x.template segment<D>(D * v) = start.row(v).transpose();
    // Simplices whose vertices are all fixed keep a constant energy: they are left out.
    std::vector<std::array<Index, D*(D + 1)>> elements;
    std::vector<Index> moving;
    std::vector<Mat<D>> rest_inverse;
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        bool moves = false;
        for (int k = 0; k <= D; ++k) moves |= !fixed[mesh.simplices(s, k)];
        if (!moves) continue;
        moving.push_back(s);
        rest_inverse.push_back(frames.edge_inverse[s]);
        std::array<Index, D*(D + 1)> e;
        for (int k = 0; k <= D; ++k) {
            for (int c = 0; c < D; ++c) e[D * k + c] = D * mesh.simplices(s, k) + c;
        }
        elements.push_back(e);
    }
    Problem problem(x);
    problem.add_term("simplex energy",
                     VertexSimplexEnergy<D>(energy.subset(moving), std::move(rest_inverse)),
                     std::move(elements));
    if constexpr (D == 2) {
        // E_theta on the positions of each boundary vertex and its fan neighbours.
        [&]<int... k>(std::integer_sequence<int, k...>) {
            (
                [&] {
                    constexpr int K = k + 1;
                    std::vector<std::array<Index, 2 * K + 4>> angle_elements;
                    for (const BoundaryFan& fan : fans) {
                        if (int(fan.triangles.size()) != K) continue;
                        std::array<Index, 2 * K + 4> e;
                        e[0] = 2 * fan.vertex;
                        e[1] = 2 * fan.vertex + 1;
                        for (int m = 0; m <= K; ++m) {
                            e[2 + 2 * m] = 2 * fan.neighbours[m];
                            e[3 + 2 * m] = 2 * fan.neighbours[m] + 1;
                        }
                        angle_elements.push_back(e);
                    }
                    if (!angle_elements.empty()) {
                        problem.add_term("boundary angle " + std::to_string(K),
                                         BoundaryAngleVertexEnergy<K>{}, std::move(angle_elements));
                    }
                }(),
                ...);
        }
        (std::make_integer_sequence<int, kMaxFan>{});
    }
    for (Index v = 0; v < nv; ++v) {
        if (!fixed[v]) continue;
        for (int c = 0; c < D; ++c) problem.set_fixed(D * v + c);
    }
    if (!std::isfinite(problem.value())) {
        result.note = "skipped: the recovered mesh has an inverted simplex or one over the bound";
        return result;
    }
    // A simplex whose e^{s d} is beyond the barrier's exponent cap (barrier.h; e^500) makes every
    // other simplex's energy vanish below the sum's rounding: Newton cannot lower the distortion
    // elsewhere, and on tlc/armadillo-598, where the fixed boundary forces such simplices, its
    // factorizations failed at every tau. The start is kept.
    Index beyond_cap = 0;
    for (Index s : moving) {
        Eigen::Matrix<double, D, D + 1> corners;
        for (int k = 0; k <= D; ++k) corners.col(k) = start.row(mesh.simplices(s, k)).transpose();
        const Mat<D> A = linear_part<D>(frames, s, corners);
        if (energy.options().barrier.s * energy.barrier_distortion(A) > kBarrierExponentCap)
            ++beyond_cap;
    }
    if (beyond_cap > 0) {
        result.note = "skipped: " + std::to_string(beyond_cap) +
                      " simplices are so distorted that the barrier cannot rank the others";
        return result;
    }
    NewtonOptions newton;
    newton.max_iterations = options.max_iterations;
    newton.max_time_seconds = options.max_time_seconds;
    newton.gradient_tolerance = 0.0;  // scale-dependent; the two relative tests decide
    newton.function_tolerance = options.energy_tolerance;
    newton.projection = options.projection;
    newton.projection_epsilon = options.projection_epsilon;
    newton.linear_solver = options.linear_solver;
    newton.num_threads = options.num_threads;
    newton.callbacks.push_back([&](const IterationContext& c) {
        if (c.record.iteration > 0) {
            char line[160];
            std::snprintf(line, sizeof line, "P%3d  %10.4e  %9s  %9s  %8.2e  %2d  %6.2fs",
                          c.record.iteration, c.record.energy, "-", "-", c.record.step_length,
                          c.record.line_search_trials, c.record.cumulative_time);
            log_line(logger, line);
        }
        return CallbackResult::kContinue;
    });
    result.newton = solve(problem, newton);
    result.ran = true;
    result.note = to_string(result.newton.termination);
    for (Index v = 0; v < nv; ++v)
        result.positions.row(v) = problem.variables().template segment<D>(D * v).transpose();
    return result;
}

template VertexStage run_vertex_stage<2>(const SimplicialMesh&, const RestFrames<2>&,
                                         const SimplexEnergy<2>&, const Eigen::MatrixXd&,
                                         const std::vector<unsigned char>&,
                                         const SimplexAssemblyOptions&, const Logger&,
                                         const std::vector<BoundaryFan>&);
template VertexStage run_vertex_stage<3>(const SimplicialMesh&, const RestFrames<3>&,
                                         const SimplexEnergy<3>&, const Eigen::MatrixXd&,
                                         const std::vector<unsigned char>&,
                                         const SimplexAssemblyOptions&, const Logger&,
                                         const std::vector<BoundaryFan>&);

}  // namespace sa
