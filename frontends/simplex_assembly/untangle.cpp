#include "frontends/simplex_assembly/untangle.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "energies/untangling_energy.h"
#include "frontends/simplex_assembly/engine.h"
#include "optim/errors.h"

namespace sa {

namespace {

/// eps once every det A is well above zero: f_eps is then the plain distortion.
constexpr double kFinalEpsilon = 1e-10;
/// The smallest relative decrease the eps rule assumes (Garanzha et al.'s 0.1).
constexpr double kMinimumDecrease = 0.1;

struct DeterminantStats {
    double min = kInfinity;
    Index nonpositive = 0;
};

}  // namespace

template <int D>
UntangleResult untangle(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                        const Eigen::MatrixXd& start, const std::vector<unsigned char>& fixed,
                        const UntangleOptions& options, const Logger& logger) {
    UntangleResult result;
    result.positions = start;
    const Index nv = mesh.num_vertices();

    // The simplices with a free vertex; the others cannot change.
    std::vector<Index> moving;
    std::vector<double> weights;
    double total_volume = 0.0;
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        bool moves = false;
        for (int k = 0; k <= D; ++k) moves |= !fixed[mesh.simplices(s, k)];
        if (!moves) continue;
        moving.push_back(s);
        weights.push_back(frames.volume[s]);
        total_volume += frames.volume[s];
    }
    // Weights relative to the moving volume: the energy is a mean distortion, O(1) when untangled.
    for (double& w : weights) w /= total_volume;
    const Index m = static_cast<Index>(moving.size());

    // The engine in its vertex layout, with f_eps as the only per-simplex energy and no assembly
    // term: projected Newton, ended by the eps rule's hook below or the limits.
    std::vector<std::array<Index, D + 1>> simplices(mesh.num_simplices());
    for (Index s = 0; s < mesh.num_simplices(); ++s)
        for (int k = 0; k <= D; ++k) simplices[s][k] = mesh.simplices(s, k);
    if (!options.shared_coordinates.empty() &&
        options.shared_coordinates.size() != static_cast<std::size_t>(D * nv)) {
        throw InvalidArgumentError("untangle: shared_coordinates has " +
                                   std::to_string(options.shared_coordinates.size()) +
                                   " entries for " + std::to_string(D * nv) + " coordinates");
    }
    SimplexAssemblyEngine<D> engine = SimplexAssemblyEngine<D>::vertex_positions(
        start.leftCols(D), std::move(simplices), frames.corners, frames.edge_inverse,
        options.shared_coordinates);

    // det A of every moving simplex at x: the quantity eps is measured against.
    auto determinants = [&](const Eigen::VectorXd& at) {
        return tbb::parallel_reduce(
            tbb::blocked_range<Index>(0, m, 1024), DeterminantStats{},
            [&](const tbb::blocked_range<Index>& r, DeterminantStats acc) {
                for (Index k = r.begin(); k != r.end(); ++k) {
                    const double det = engine.linear_part(at, moving[k]).determinant();
                    acc.min = std::min(acc.min, det);
                    acc.nonpositive += det > 0.0 ? 0 : 1;
                }
                return acc;
            },
            [](DeterminantStats a, const DeterminantStats& b) {
                a.min = std::min(a.min, b.min);
                a.nonpositive += b.nonpositive;
                return a;
            });
    };
    auto parameters = std::make_shared<UntanglingParameters>();
    if (m > 0) {
        engine.add_simplex_energy("untangling", UntanglingEnergy<D>(std::move(weights), parameters),
                                  moving);
    }
    for (Index v = 0; v < nv; ++v)
        if (fixed[v]) engine.fix_vertex(v);
    if (!options.fixed_coordinates.empty()) {
        if (options.fixed_coordinates.size() != static_cast<std::size_t>(D * nv)) {
            throw InvalidArgumentError("untangle: fixed_coordinates has " +
                                       std::to_string(options.fixed_coordinates.size()) +
                                       " flags for " + std::to_string(D * nv) + " coordinates");
        }
        for (Index i = 0; i < D * nv; ++i) {
            if (options.fixed_coordinates[i])
                engine.problem().set_fixed(engine.coordinate_variable(i));
        }
    }
    Eigen::VectorXd x = engine.problem().variables();

    DeterminantStats stats = determinants(x);
    result.min_det = stats.min;
    result.inverted = stats.nonpositive;
    result.untangled = stats.nonpositive == 0;
    auto positions_of = [&](const Eigen::VectorXd& at) { return engine.positions(at); };
    auto accepted = [&](const Eigen::VectorXd& at) {
        return options.until_valid && (!options.accept || options.accept(positions_of(at)));
    };
    if (m == 0 || (result.untangled && accepted(x))) {
        result.outcome = m == 0 ? UntangleOutcome::kNothingFree : UntangleOutcome::kStartUntangled;
        return result;
    }
    // Garanzha et al. start from eps = 1 on a mesh scaled so that det A is about 1 where the map
    // keeps the rest size, as here (rest and map share the driver's normalization).
    parameters->epsilon = 1.0;
    Eigen::VectorXd best_valid;  // the last untangled iterate
    if (result.untangled) best_valid = x;
    bool converged = false;

    AssemblyEngineOptions run_options;
    run_options.max_iterations = options.max_iterations;
    run_options.max_time_seconds = options.max_time_seconds;
    // eps changes between steps, so Newton's own tests (at fixed weights) do not apply.
    run_options.stop_when_converged = false;
    run_options.projection = options.projection;
    run_options.projection_epsilon = options.projection_epsilon;
    run_options.linear_solver = options.linear_solver;
    run_options.num_threads = options.num_threads;
    AssemblyHooks hooks;  // no logger: the rows below say more than the engine's
    log_line(logger, "untangle   energy    eps        min det    inverted  step      time");
    hooks.after_iteration = [&](const AssemblyRecord& record, const Eigen::VectorXd& at) {
        if (record.iteration == 0) return false;
        stats = determinants(at);
        const double eps = parameters->epsilon;
        char line[160];
        std::snprintf(line, sizeof line, "U%4d  %10.4e  %9.3e  %10.3e  %7ld  %8.2e  %6.2fs",
                      record.iteration, record.energy, eps, stats.min, long(stats.nonpositive),
                      record.step, record.time);
        log_line(logger, line);
        const double energy = record.energy;
        const double before = energy + record.energy_change;  // at the same eps
        if (stats.nonpositive == 0) {
            best_valid = at;
            if (accepted(at)) return true;
            if (eps <= kFinalEpsilon &&
                record.energy_change <= options.energy_tolerance * std::abs(energy)) {
                converged = true;
                return true;
            }
        }
        // Lower eps only after a full Newton step: a damped one says that Newton is not yet in
        // its local regime for this eps (Garanzha et al. lower it after an inner solve to
        // convergence). Without this rule a faster schedule stalled (docs/measurements.md).
        if (record.step < 1.0) return false;
        const double sigma = std::max(1.0 - energy / before, kMinimumDecrease);
        const double mu = (1.0 - sigma) * regularized_determinant(stats.min, eps).value;
        parameters->epsilon =
            stats.min < mu ? 2.0 * std::sqrt(mu * (mu - stats.min)) : kFinalEpsilon;
        return false;
    };
    AssemblyRun run = engine.run(run_options, hooks);
    result.newton = std::move(run.newton);
    result.iterations = result.newton.num_steps();
    result.epsilon = parameters->epsilon;
    const Eigen::VectorXd& final_x =
        best_valid.size() > 0 ? best_valid : engine.problem().variables();
    stats = determinants(final_x);
    result.min_det = stats.min;
    result.inverted = stats.nonpositive;
    result.untangled = stats.nonpositive == 0;
    result.positions = positions_of(final_x);
    result.stop = run.stop;
    result.outcome = !result.untangled ? UntangleOutcome::kNotUntangled
                     : converged       ? UntangleOutcome::kUntangledConverged
                                       : UntangleOutcome::kUntangled;
    const std::string how = result.untangled
                                ? to_string(result.outcome)
                                : to_string(result.outcome) + ": " + to_string(run.stop);
    char line[160];
    std::snprintf(line, sizeof line, "untangling: %s after %d steps, %.2f s (", how.c_str(),
                  result.iterations, result.newton.times.total);
    log_line(logger, line + result.newton.phase_times() + ")");
    return result;
}

template UntangleResult untangle<2>(const SimplicialMesh&, const RestFrames<2>&,
                                    const Eigen::MatrixXd&, const std::vector<unsigned char>&,
                                    const UntangleOptions&, const Logger&);
template UntangleResult untangle<3>(const SimplicialMesh&, const RestFrames<3>&,
                                    const Eigen::MatrixXd&, const std::vector<unsigned char>&,
                                    const UntangleOptions&, const Logger&);

}  // namespace sa
