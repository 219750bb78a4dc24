#include "frontends/deform/deform_solve.h"

#include <cstdio>

#include "energies/difference_energy.h"
#include "energies/distortion_barrier.h"
#include "geometry/mesh/rest_frames.h"
#include "geometry/quality/map_quality.h"
#include "optim/stopwatch.h"

namespace sa {

namespace {

template <int D>
void add_terms(MappingProblem& problem, const DeformOptions& options) {
    const RestFrames<D> frames = rest_frames<D>(problem.mesh);
    std::vector<Mat<D>> references = linear_parts<D>(problem.mesh, frames, problem.reference);
    problem.energies.push_back(simplex_term<D>(
        "E_m", DifferenceEnergy<D>(std::move(references), std::vector<double>{options.mu})));
    problem.energies.push_back(simplex_term<D>(
        kVolumetricBarrierName, DistortionBarrier<D, BuiltinDistortion<D>>(
                                    BuiltinDistortion<D>(DistortionType::kVolumetric),
                                    BarrierOptions{options.volumetric_bound, 1.0})));
}

}  // namespace

MappingProblem deform_problem(const SimplicialMesh& mesh, const HandleTargets& handle_targets,
                              const Eigen::MatrixXd& start, const DeformOptions& options) {
    MappingProblem problem;
    problem.mesh = mesh;
    problem.initial = start;
    problem.reference = start;
    problem.handles = handle_targets.handles;
    problem.targets = handle_targets.targets;
    problem.source = "deform";
    if (mesh.simplex_dimension() == 2) {
        add_terms<2>(problem, options);
    } else {
        add_terms<3>(problem, options);
    }
    return problem;
}

SimplexAssemblyOptions deform_solver_options(const DeformOptions& options) {
    SimplexAssemblyOptions solver;
    solver.distortion = DistortionType::kConformal;
    solver.bound = options.conformal_bound;
    solver.mapping_distortion.reset();  // E_m is the problem's own unit-weight difference
    solver.initialization = options.initialization;
    solver.max_time_seconds = options.max_time_seconds;
    solver.num_threads = options.num_threads;
    return solver;
}

std::string DeformResult::distortion_warning() const {
    const double start_mean = start.quality.isometric.mean,
                 result_mean = solve.solve.final_quality.isometric.mean;
    if (!(result_mean > kDistortionWarningRatio * start_mean)) return {};
    char line[300];
    std::snprintf(line, sizeof line,
                  "the result's mean isometric distortion %.4g is %.3g times the ARAP start's "
                  "%.4g: the repair of the start's folds distorted simplices the vertex stage "
                  "could not bring back",
                  result_mean, result_mean / start_mean, start_mean);
    return line;
}

DeformResult deform(const SimplicialMesh& mesh, const HandleTargets& handle_targets,
                    const DeformOptions& options, const SimplexAssemblyObserver& observer) {
    options.validate();
    const Stopwatch watch;
    DeformResult result;
    result.start = deform_start(mesh, handle_targets, options.start, observer.logger);
    result.problem = deform_problem(mesh, handle_targets, result.start.positions, options);
    result.solver = deform_solver_options(options);
    result.solver.max_time_seconds = std::max(options.max_time_seconds - watch.seconds(), 1e-3);
    OptimalBoundOptions rounds;
    rounds.rounds = options.optimal_bound ? options.optimal_bound_rounds : 1;
    // As sa param's rounds: the first in the mode kAuto picks (it may have folds to repair), the
    // others in the submesh mode around the simplices near either bound, each next bound just
    // above the largest distortion so that the previous pose stays a feasible start.
    rounds.tolerance = options.optimal_bound_tolerance;
    rounds.submesh_band = options.optimal_bound_band;
    rounds.margin = 1e-6;
    result.solve = optimal_bound(result.problem, result.solver, rounds, observer);
    result.seconds = watch.seconds();
    return result;
}

}  // namespace sa
