#include "frontends/simplex_assembly/vertex_descent.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "frontends/simplex_assembly/bound_rounds.h"
#include "frontends/simplex_assembly/detail/prepared_problem.h"
#include "frontends/simplex_assembly/detail/vertex_stage.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"
#include "optim/time_budget.h"

namespace sa {

namespace {

/// Each next bound d + (d - I) / 10: the simplex at the maximum starts well inside the barrier,
/// which Newton in vertex variables must move first; a round goes on when it lowers d - I by 1%.
/// The continuation's rounds, then the round at the bound.
constexpr BoundRule kDescentBoundRule{
    .max_rounds = kContinuationRounds + 1, .headroom = 0.1, .tolerance = kContinuationStall};

template <int D>
VertexDescentResult descend(const MappingProblem& input, const SimplexAssemblyOptions& options,
                            const SimplexAssemblyObserver& observer) {
    Stopwatch total, stage;
    const TimeBudget budget(options.max_time_seconds);
    VertexDescentResult out;
    SimplexAssemblyResult& result = out.solve;
    std::unique_ptr<PreparedProblem<D>> p = prepare_problem<D>(input, options, result.times);
    const PreparedProblem<D>& prepared = *p;
    result.initial_quality = prepared.initial_quality;
    result.mode = SolveMode::kFull;
    // The barrier is finite where det A > 0: a start whose triangles are all positively oriented
    // can run, even if some are degenerate by the verification's relative rule.
    out.start_valid =
        std::all_of(prepared.initial_quality.per_simplex.begin(),
                    prepared.initial_quality.per_simplex.end(),
                    [](const SimplexQuality& q) { return q.det > 0.0 && std::isfinite(q.det); }) &&
        (prepared.assembly.fans.empty() ||
         count_boundary_violations(prepared.assembly.fans, prepared.initial_map) == 0);
    Eigen::MatrixXd x = prepared.start;
    // The anchored simplices keep all their vertices: a free part has no rigid motion left.
    std::vector<unsigned char> fixed = prepared.recovery_fixed;
    for (Index s : prepared.assembly.anchored_simplices) {
        for (int k = 0; k <= D; ++k) fixed[prepared.mesh.simplices(s, k)] = 1;
    }
    const SimplexEnergyOptions base = simplex_energy_options(options);
    const std::vector<Mat<D>> references = options.mapping_distortion == DistortionType::kDifference
                                               ? prepared.assembly.reference_linear
                                               : std::vector<Mat<D>>{};
    const SimplexEnergy<D> measure(base, prepared.frames.volume, references);
    auto largest_distortion = [&](const Eigen::MatrixXd& positions) {
        double largest = 0.0;
        for (const Mat<D>& A : linear_parts<D>(prepared.mesh, prepared.frames, positions))
            largest = std::max(largest, measure.barrier_distortion(A));
        return largest;
    };
    result.times.setup += stage.lap();

    // Each round is a run of the vertex stage at one bound, with E_C's exponent continuation
    // (vertex_stage.h): its rounds raise s to options.s; a run that left degenerate simplices
    // where its start had none was undone there, and ends the descent.
    bool undone = false;
    auto run_round = [&](double bound) {
        auto energies_at = [&](double s) {
            SimplexEnergyOptions e = base;
            e.barrier.s = s;
            e.barrier.bound = bound;
            return std::vector<std::shared_ptr<const SimplexTerm<D>>>{simplex_term<D>(
                "simplex energy", SimplexEnergy<D>(e, prepared.frames.volume, references))};
        };
        ExponentContinuation<D> continuation;
        continuation.s = options.s;
        continuation.distortion = [&measure](const Mat<D>& A) {
            return measure.barrier_distortion(A);
        };
        continuation.energies = energies_at;
        char line[200];
        std::snprintf(line, sizeof line,
                      "vertex descent round %d: bound %.4g, largest distortion %.4g",
                      int(out.rounds.size()), bound, largest_distortion(x));
        log_line(observer.logger, line);
        SimplexAssemblyOptions o = with_time_left(options, budget);
        o.bound = bound;
        const VertexStage v = run_vertex_stage<D>(
            prepared.mesh, prepared.frames, energies_at(options.s), x, fixed, o, observer.logger,
            VertexStageTerms<D>{prepared.assembly.fans, {}, {}, {}, continuation});
        for (const ContinuationRound& r : v.rounds) {
            out.rounds.push_back(DescentRound{r, bound});
            undone |= r.outcome == VertexStageOutcome::kRanUndone;
        }
        if (v.ran()) {
            x = v.positions;
            result.vertex_stage = v.newton;
        }
        record_vertex_stage(result.stages, v, v.newton.times.total);
        return largest_distortion(x);
    };

    if (out.start_valid) {
        // The exponent's continuation, bounded from the start when the start is within K; then
        // the bound's continuation (bound_rounds.h) for a start that was over it.
        const double d = largest_distortion(x);
        const double first_bound = d < options.bound ? options.bound : kInfinity;
        const double after = run_round(first_bound);
        if (!undone) {
            const RoundedBound rounded{.target = options.bound,
                                       .identity = measure.barrier_distortion(Mat<D>::Identity())};
            run_bound_rounds(kDescentBoundRule, {rounded}, {first_bound}, {after}, budget,
                             [&](const std::vector<double>& bounds) {
                                 const double reached = run_round(bounds[0]);
                                 if (undone) return std::optional<std::vector<double>>();
                                 return std::optional(std::vector<double>{reached});
                             });
        }
    }
    result.times.vertex_stage += stage.lap();
    result.newton.num_threads = result.vertex_stage.num_threads;  // no assembly ran
    result.positions = prepared.to_original(x);
    verify_result<D>(input, options, result, &prepared.topology);
    verify_boundary_angles<D>(prepared, result);
    if (!out.start_valid) result.success = false;
    std::ostringstream message;
    message << (!result.success                      ? "FAILED: "
                : result.verification.within_bound() ? "success: "
                                                     : "no foldovers, over the bound: ")
            << result.verification.describe() << ". ";
    if (!out.start_valid) {
        message << "The start is not valid (" << prepared.initial_quality.inverted << " inverted, "
                << prepared.initial_quality.degenerate << " degenerate): no descent ran";
    } else {
        int steps = 0;
        for (const DescentRound& r : out.rounds) steps += r.iterations;
        message << "Newton on the vertex positions from the valid start: " << out.rounds.size()
                << " round" << (out.rounds.size() == 1 ? "" : "s") << ", " << steps
                << " iterations";
        if (!out.rounds.empty()) {
            const DescentRound& last = out.rounds.back();
            message << ", s " << out.rounds.front().s << " to " << last.s << " ("
                    << (newton_ran(last.outcome) ? to_string(result.vertex_stage.termination)
                                                 : to_string(last.outcome));
            if (last.undone_degenerate > 0)
                message << "; undone: it left " << last.undone_degenerate
                        << " degenerate simplices, its start none";
            message << ")";
        }
        if (!result.verification.within_bound()) {
            message << "; the bound " << options.bound << " was not reached (largest distortion "
                    << result.verification.max_distortion << ")";
        }
    }
    message << ".";
    result.message = message.str();
    result.times.total = total.seconds();
    return out;
}

}  // namespace

VertexDescentResult run_vertex_descent(const MappingProblem& problem,
                                       const SimplexAssemblyOptions& options,
                                       const SimplexAssemblyObserver& observer) {
    options.validate();
    switch (problem.mesh.simplex_dimension()) {
        case 2:
            return descend<2>(problem, options, observer);
        case 3:
            return descend<3>(problem, options, observer);
        default:
            throw InputError(problem.source + ": simplices have " +
                             std::to_string(problem.mesh.simplices.cols()) +
                             " vertices, expected 3 or 4");
    }
}

}  // namespace sa
