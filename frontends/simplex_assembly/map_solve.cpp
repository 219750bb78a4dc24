#include "frontends/simplex_assembly/map_solve.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "frontends/simplex_assembly/detail/prepared_problem.h"
#include "frontends/simplex_assembly/detail/round_verification.h"
#include "frontends/simplex_assembly/detail/submesh_assembly.h"
#include "frontends/simplex_assembly/detail/untangle_fallback.h"
#include "frontends/simplex_assembly/detail/vertex_descent.h"
#include "frontends/simplex_assembly/detail/vertex_stage.h"
#include "frontends/simplex_assembly/translation_gluing.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"
#include "optim/time_budget.h"

namespace sa {

std::string Verification::describe() const {
    std::ostringstream out;
    out << "verified from the output positions: " << inverted << " of " << simplices
        << " simplices inverted, " << degenerate << " degenerate";
    if (branched > 0) {
        out << ", " << branched
            << " branch points (an interior vertex or edge the map wraps around more than once: "
               "not locally injective; the first at "
            << first_branch << ")";
    }
    if (handles > 0) {
        out << ", largest handle error " << handle_error << " (tolerance " << handle_tolerance
            << ", " << handles << " handles)";
    }
    if (bound < kInfinity) {
        out << ", largest distortion " << max_distortion
            << (max_distortion <= bound ? " <= " : " > ") << "bound " << bound;
    }
    for (const BoundCheck& b : bounds) {
        out << ", largest " << b.name << " " << b.max_distortion << (b.within() ? " <= " : " > ")
            << "bound " << b.bound;
    }
    if (constraints > 0) {
        out << ", largest constraint error " << constraint_error << " (tolerance "
            << constraint_tolerance << ", " << constraints << " constraints)";
    }
    return out.str();
}

std::string StartChoice::describe() const {
    std::string out;
    switch (iterate) {
        case StartIterate::kInitialMap:
            out = "initial map";
            break;
        case StartIterate::kHandleRotations:
            out = "the handles' rotations";
            break;
        case StartIterate::kM0:
            out = "M^0 (Eq. 6)";
            break;
        case StartIterate::kLocalGlobal:
            out = std::string(similarity ? "ASAP" : "ARAP") + " iteration " +
                  std::to_string(local_global_iteration);
            break;
    }
    if (from_handle_rotations) out += " from the handles' rotations";
    if (branch_points_removed > 0) {
        out += " without its " + std::to_string(branch_points_removed) + " branch point" +
               (branch_points_removed == 1 ? "" : "s");
    }
    if (small_regions) out += " (its regions are small)";
    if (untangled) out = "untangling (regularized barrier) from the " + out;
    return out;
}

std::string SubmeshStats::describe() const {
    std::ostringstream out;
    out << "Submesh mode: " << start_bad << " bad simplices in the start (" << start.describe()
        << "), ";
    if (start_near_bound > 0) out << start_near_bound << " near the bound, ";
    out << rounds.size() << " round" << (rounds.size() == 1 ? "" : "s") << ", " << solves
        << " submesh solves (largest " << largest_submesh << " simplices, up to " << max_rings
        << " rings, " << iterations << " Newton steps in all)";
    if (!rounds.empty()) out << ", " << rounds.back().remaining << " bad simplices left";
    if (out_of_time) out << "; stopped at the time limit";
    return out.str();
}

namespace {

/// When the assembly ended on a recovered mesh the vertex stage cannot start from (an inverted
/// simplex, one over the bound), the initial map with its handles at their targets is the other
/// candidate, as in the submesh mode's start: the vertex stage runs from it when its energy is
/// finite; when it is not (a distortion whose barrier e^{s d} overflows, a handle moved 1e6 away
/// from a fixed boundary) but it is inversion-free and no bound is set, it is kept as it is. On
/// a 3 x 3 grid with its boundary fixed and a corner moved to (30, 30) the assembly stalled at
/// lambda_max with an inverted triangle (e^{58} against lambda_max = 1e16) although the initial
/// map was a solution. `recovered` and `vertex` are replaced only when the candidate is used.
template <int D>
void start_from_initial_map(PreparedProblem<D>& prepared, const SimplexAssemblyOptions& options,
                            const TimeBudget& budget, const SimplexAssemblyObserver& observer,
                            const std::vector<unsigned char>& fixed, Eigen::MatrixXd& recovered,
                            VertexStage& vertex) {
    const AssemblyInput<D>& in = prepared.assembly;
    Eigen::MatrixXd candidate = prepared.start;
    for (std::size_t k = 0; k < in.handles.size(); ++k)
        candidate.row(in.handles[k]) = in.targets[k].transpose();
    VertexStage from_initial = run_vertex_stage<D>(
        prepared.mesh, prepared.frames, prepared.topology, in.energies, candidate, fixed,
        with_time_left(options, budget), observer.logger,
        VertexStageTerms<D>{in.fans, in.constraints, in.plugins, in.plugin_stage,
                            exponent_continuation<D>(prepared)});
    // Why the recovered mesh was no start, for the record.
    const std::string recovered_mesh = "the recovered mesh: " + to_string(vertex.outcome) +
                                       (vertex.figures.empty() ? "" : " (" + vertex.figures + ")");
    if (from_initial.ran()) {
        from_initial.outcome = VertexStageOutcome::kRanFromInitialMap;
        from_initial.figures = from_initial.figures.empty()
                                   ? recovered_mesh
                                   : recovered_mesh + "; " + from_initial.figures;
        recovered = from_initial.positions;
        vertex = std::move(from_initial);
        return;
    }
    if (options.bound < kInfinity || !in.fans.empty() || !in.constraints.empty() ||
        !in.plugins.empty())
        return;
    for (const auto& energy : in.energies)
        if (energy->bounds_a_distortion() && energy->bound() < kInfinity) return;
    const MapQuality q = map_quality<D>(linear_parts<D>(prepared.mesh, prepared.frames, candidate),
                                        prepared.frames.volume);
    if (q.inverted > 0 || q.degenerate > 0) return;
    recovered = candidate;
    vertex.positions = candidate;
    vertex.outcome = VertexStageOutcome::kInitialMapKept;
    vertex.figures = recovered_mesh;
}

/// The whole mesh at once: the engine (its lambda schedule, section 4.4) with the hand-over of
/// Eq. 6 as its hook, recovery, and the vertex stage. Fills positions (original units) and the
/// solver records of `result`.
template <int D>
void solve_full(PreparedProblem<D>& prepared, const SimplexAssemblyOptions& options,
                const TimeBudget& budget, const SimplexAssemblyObserver& observer,
                SimplexAssemblyResult& result) {
    Stopwatch stage;
    const AssemblyInput<D>& in = prepared.assembly;
    const SimplicialMesh& mesh = prepared.mesh;
    const RestFrames<D>& frames = prepared.frames;
    const Index n = mesh.num_simplices();
    AssemblyProblem<D> assembly(in, options);
    SimplexAssemblyEngine<D>& engine = assembly.engine();
    result.num_variables = engine.problem().num_variables();
    result.num_translation_simplices = assembly.num_translation_simplices();
    result.num_tree_edges = assembly.num_tree_edges();
    result.num_loops = assembly.num_loops();
    result.num_anchored_simplices = static_cast<Index>(in.anchored_simplices.size());
    result.times.setup += stage.lap();

    auto corners_of = [&](const Eigen::VectorXd& x) {
        const std::vector<Mat<D>> A = assembly.linear_parts(x);
        const std::vector<Vec<D>> T =
            glue_translations<D>(mesh, prepared.topology, frames, A, assembly.known_translations(x),
                                 in.start_translation);
        Eigen::MatrixXd corners((D + 1) * n, D);
        for (Index s = 0; s < n; ++s) {
            for (int k = 0; k <= D; ++k)
                corners.row((D + 1) * s + k) = (A[s] * frames.corner(s, k) + T[s]).transpose();
        }
        return prepared.to_original(corners);
    };
    // With a time limit, a run whose assembly goes nowhere must leave time for the untangling
    // fallback (untangle_fallback.h): the assembly takes at most half of what is left.
    SimplexAssemblyOptions assembly_options = with_time_left(options, budget);
    if (options.untangle_fallback && std::isfinite(options.max_time_seconds))
        assembly_options.max_time_seconds *= 0.5;
    AssemblyEngineOptions schedule = assembly_options;  // the engine's part of them
    // The 1e-6 lambda shift is meant for r-SA's few, possibly redundant translations
    // (docs/algorithm.md, "Departures from the paper").
    if (options.variant != Variant::kReduced) schedule.translation_shift = 0.0;
    Eigen::MatrixXd handover;  // the feasible recovered mesh that ended the assembly, if any
    AssemblyHooks hooks;
    hooks.logger = observer.logger;
    hooks.after_iteration = [&](const AssemblyRecord& row, const Eigen::VectorXd& x) {
        if (observer.snapshot) observer.snapshot(row.iteration, corners_of(x));
        if (!options.vertex_stage && !options.until_valid) return false;
        // Hand over as soon as the mesh recovered from the current A_i is inversion-free and
        // within the bound: one right-hand side and triangular solves of Eq. 6.
        Stopwatch check;
        Eigen::MatrixXd positions =
            prepared.recovery().recover(assembly.linear_parts(x), prepared.pinned);
        // The plugins' constraint sets: the mesh is handed over as the vertex stage will start.
        PluginStage<D> stage = in.plugin_stage;
        stage.kind = PluginStage<D>::Kind::kVertex;
        stage.fixed = &prepared.recovery_fixed;
        for (const auto& plugin : in.plugins) {
            if (!plugin->project(positions, stage)) {
                result.times.recovery += check.seconds();
                return false;
            }
        }
        const double recovered_energy = mesh_energy<D>(prepared, positions);
        const bool ok = options.until_valid
                            ? std::isfinite(recovered_energy)
                            : std::isfinite(recovered_energy) &&
                                  recovered_energy <= options.handover_ratio * row.barrier;
        result.times.recovery += check.seconds();
        if (!ok) return false;
        handover = std::move(positions);
        return true;
    };
    AssemblyRun run = engine.run(schedule, hooks);
    StageRecord& assembled = result.stages.add(Stage::kAssembly, run.stop);
    assembled.newton_steps = run.newton.num_steps();
    assembled.termination = run.newton.termination;
    assembled.seconds = run.time;
    if (run.stop == AssemblyStop::kHook) {
        assembled.figures = options.until_valid ? "the recovered map is valid"
                                                : "the recovered map is handed to the vertex stage";
    }
    result.iterations = std::move(run.records);
    result.newton = std::move(run.newton);
    result.final_lambda = run.final_lambda;
    result.final_assembly = run.final_assembly;
    result.assembled = run.assembled;
    result.times.optimization += stage.lap();
    // Recovery: positions by Eq. 6 with the handles at their targets (translations are not needed:
    // every part has a handle or an anchored simplex, whose start image is pinned).
    Eigen::MatrixXd recovered =
        handover.size() > 0
            ? handover
            : prepared.recovery().recover(assembly.linear_parts(engine.problem().variables()),
                                          prepared.pinned);
    result.times.recovery += stage.lap();

    if (options.vertex_stage && !options.until_valid && budget.exhausted()) {
        result.stages.add(Stage::kVertexStage, VertexStageOutcome::kSkippedTimeLimit);
    } else if (options.vertex_stage && !options.until_valid) {
        const std::vector<unsigned char> fixed = vertex_stage_fixed(prepared);
        VertexStage vertex = run_vertex_stage<D>(
            mesh, frames, prepared.topology, in.energies, recovered, fixed,
            with_time_left(options, budget), observer.logger,
            VertexStageTerms<D>{in.fans, in.constraints, in.plugins, in.plugin_stage,
                                exponent_continuation<D>(prepared)});
        if (!vertex.ran())
            start_from_initial_map<D>(prepared, options, budget, observer, fixed, recovered,
                                      vertex);
        result.vertex_stage = vertex.newton;
        recovered = vertex.positions;
        const double seconds = stage.lap();
        result.times.vertex_stage += seconds;
        record_vertex_stage(result.stages, vertex, seconds);
    }
    result.positions = prepared.to_original(recovered);
}

/// The options with the Hessian projection's clamp at the map's scale. The clamp is absolute,
/// while the barrier's Hessian (in the linear parts or in the positions, the rest normalized to
/// a unit diagonal) scales as 1/c^2 with the map's size c: with a handle moved to (1e6, 1e6)
/// every eigenvalue fell under the clamp and Newton crawled (conformal distortion 3.47 after 200
/// iterations where a similarity, 1, is the answer). It is scaled by the power of 4 nearest
/// 1/c^2, so that a map gets the clamp it would have at unit scale; maps of the rest's size (c
/// in [0.71, 1.41)) keep it unchanged. `pinned` is the normalized initial map with its handles at
/// their targets.
SimplexAssemblyOptions at_map_scale(const SimplexAssemblyOptions& options,
                                    const Eigen::MatrixXd& pinned) {
    SimplexAssemblyOptions scaled = options;
    const double c = bounding_box_diagonal(pinned);
    if (c > 0.0 && std::isfinite(c)) {
        const long k = std::lround(std::log2(c));
        scaled.projection_epsilon = std::ldexp(options.projection_epsilon, int(-2 * k));
    }
    return scaled;
}

template <int D>
SimplexAssemblyResult run(const MappingProblem& input, const SimplexAssemblyOptions& options,
                          const SimplexAssemblyObserver& observer) {
    Stopwatch total;
    const TimeBudget budget(options.max_time_seconds);
    StageTimes times;
    std::unique_ptr<PreparedProblem<D>> prepared = prepare_problem<D>(input, options, times);
    times.total = total.seconds();
    // What is left of the budget, overrun included (with_time_left() would grant 1 ms more).
    SimplexAssemblyOptions rest = options;
    rest.max_time_seconds = budget.remaining();
    return solve_prepared<D>(*prepared, rest, observer, times);
}

}  // namespace

template <int D>
SimplexAssemblyResult solve_prepared(PreparedProblem<D>& p, const SimplexAssemblyOptions& options,
                                     const SimplexAssemblyObserver& observer,
                                     const StageTimes& preparation, VerifiedMap* changes) {
    Stopwatch total;
    const TimeBudget budget(options.max_time_seconds);
    const MappingProblem& input = *p.input;
    PreparedProblem<D>* prepared = &p;
    SimplexAssemblyResult result;
    result.times = preparation;
    result.initial_quality = prepared->initial_quality;
    result.mode = choose_mode<D>(*prepared, options);
    const SimplexAssemblyOptions solve_options = at_map_scale(options, prepared->pinned);
    if (result.mode == SolveMode::kSubmesh) {
        solve_submeshes<D>(*prepared, solve_options, budget, observer, result);
    } else if (result.mode == SolveMode::kDescent) {
        // At the caller's clamp: the descent's start is the caller's map, not the pinned one
        // whose scale at_map_scale() measures.
        solve_descent<D>(*prepared, options, budget, observer, result);
    } else if (prepared->assembly.start_linear.empty() && prepared->mesh.num_simplices() > 0) {
        throw InvalidArgumentError(input.source +
                                   ": a restarted problem (restart_problem) has no disassembly: "
                                   "the full mode needs prepare_problem");
    } else {
        solve_full<D>(*prepared, solve_options, budget, observer, result);
    }
    for (Index v = 0; v < input.mesh.num_vertices(); ++v) {
        if (!prepared->topology.used_vertex[v])
            result.positions.row(v) = prepared->initial_map.row(v);  // untouched
    }
    Stopwatch stage;
    if (changes != nullptr && D == 2) {
        verify_changes<D>(*prepared, options, result, *changes);
    } else {
        verify_result<D>(input, options, result, &prepared->topology);
    }
    // A descent that could not start returns its start, whatever the verification says of it.
    if (result.mode == SolveMode::kDescent && !descent_started(result)) result.success = false;
    // The last resort (untangle_fallback.h): no valid map, but the handles are where they belong.
    // The fallback ignores the plugins' terms (assembly_plugin.h): not for problems with them.
    if (!result.success && options.untangle_fallback && input.plugins.empty() &&
        result.verification.handle_error <= result.verification.handle_tolerance &&
        untangle_fallback<D>(*prepared, options, budget, observer, result)) {
        for (Index v = 0; v < input.mesh.num_vertices(); ++v) {
            if (!prepared->topology.used_vertex[v])
                result.positions.row(v) = prepared->initial_map.row(v);
        }
        verify_result<D>(input, options, result, &prepared->topology);
        if (changes != nullptr) *changes = VerifiedMap{};  // measured whole next time
    }
    verify_boundary_angles<D>(*prepared, result);
    // A valid map over a bound the caller asked for is not what was asked (the last resort above
    // untangles without the bounds): written, and reported as a failure.
    result.valid = result.success;
    if (!result.verification.within_bound()) result.success = false;
    std::ostringstream message;
    message << (result.success ? "success: "
                : result.valid ? "no foldovers, over the bound: "
                               : "FAILED: ")
            << result.verification.describe() << ". ";
    const std::optional<AssemblyStop> stop = result.stages.outcome<AssemblyStop>(Stage::kAssembly);
    if (result.mode == SolveMode::kSubmesh) {
        message << result.submesh.describe();
    } else if (result.mode == SolveMode::kDescent) {
        message << describe_descent(result);
    } else if (result.assembled) {
        message << "Assembled (E~ = " << result.final_assembly << ") after "
                << result.newton.num_steps() << " iterations";
    } else if (stop) {
        message << "Not assembled: E~ = " << result.final_assembly << " after "
                << result.newton.num_steps() << " iterations ("
                << (*stop == AssemblyStop::kHook ? result.stages.last(Stage::kAssembly)->figures
                    : *stop == AssemblyStop::kConvergedAtLambdaMax
                        ? std::string("E converged at lambda_max")
                        : to_string(result.newton.termination))
                << ")";
    }
    // The vertex stages and the fallback, in the order they ran (the descent's rounds are
    // described above).
    bool described = result.mode == SolveMode::kDescent;
    for (const StageRecord& r : result.stages.records) {
        if (r.stage == Stage::kFallback) {
            described = false;
            message << ". Then the fallback untangled in vertex variables (" << r.figures
                    << "): " << to_string(r.outcome);
            continue;
        }
        const auto* v = std::get_if<VertexStageOutcome>(&r.outcome);
        if (r.stage != Stage::kVertexStage || v == nullptr || described) continue;
        if (newton_ran(*v)) {
            message << ", then " << r.newton_steps << " in vertex variables";
            if (r.termination) message << " (" << to_string(*r.termination) << ")";
            if (*v != VertexStageOutcome::kRan) message << "; " << to_string(*v);
        } else {
            message << "; vertex stage: " << to_string(*v);
        }
        if (!r.figures.empty()) message << " (" << r.figures << ")";
    }
    message << ".";
    result.message = message.str();
    result.times.verification += stage.lap();
    result.times.total = preparation.total + total.seconds();
    return result;
}

template SimplexAssemblyResult solve_prepared<2>(PreparedProblem<2>&, const SimplexAssemblyOptions&,
                                                 const SimplexAssemblyObserver&, const StageTimes&,
                                                 VerifiedMap*);
template SimplexAssemblyResult solve_prepared<3>(PreparedProblem<3>&, const SimplexAssemblyOptions&,
                                                 const SimplexAssemblyObserver&, const StageTimes&,
                                                 VerifiedMap*);

bool descent_started(const SimplexAssemblyResult& result) {
    // Every run of the vertex stage records at least one round, even a skipped one.
    return result.mode == SolveMode::kDescent && !result.descent_rounds.empty();
}

SimplexAssemblyResult run_simplex_assembly(const MappingProblem& problem,
                                           const SimplexAssemblyOptions& options,
                                           const SimplexAssemblyObserver& observer) {
    options.validate();
    switch (problem.mesh.simplex_dimension()) {
        case 2:
            return run<2>(problem, options, observer);
        case 3:
            return run<3>(problem, options, observer);
        default:
            throw InputError(problem.source + ": simplices have " +
                             std::to_string(problem.mesh.simplices.cols()) +
                             " vertices, expected 3 or 4");
    }
}

}  // namespace sa
