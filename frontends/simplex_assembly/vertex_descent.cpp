#include "frontends/simplex_assembly/detail/vertex_descent.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "frontends/simplex_assembly/bound_rounds.h"
#include "frontends/simplex_assembly/detail/vertex_stage.h"
#include "optim/stopwatch.h"

namespace sa {

namespace {

/// Each next bound d + (d - I) / 10: the simplex at the maximum starts well inside the barrier,
/// which Newton in vertex variables must move first; a round goes on when it lowers d - I by 1%.
/// The continuation's rounds, then the round at the bound.
constexpr BoundRule kDescentBoundRule{
    .max_rounds = kContinuationRounds + 1, .headroom = 0.1, .tolerance = kContinuationStall};

}  // namespace

template <int D>
void solve_descent(const PreparedProblem<D>& prepared, const SimplexAssemblyOptions& options,
                   const TimeBudget& budget, const SimplexAssemblyObserver& observer,
                   SimplexAssemblyResult& result) {
    Stopwatch stage;
    const AssemblyInput<D>& in = prepared.assembly;
    // The initial map with its handles at their targets (fixed there).
    Eigen::MatrixXd x = prepared.start;
    for (std::size_t k = 0; k < in.handles.size(); ++k)
        x.row(in.handles[k]) = in.targets[k].transpose();
    // The barrier is finite where det A > 0: a start whose simplices are all positively oriented
    // can run, even if some are degenerate by the verification's relative rule.
    const MapQuality start =
        map_quality<D>(linear_parts<D>(prepared.mesh, prepared.frames, x), prepared.frames.volume);
    const bool start_valid =
        std::all_of(start.per_simplex.begin(), start.per_simplex.end(),
                    [](const SimplexQuality& q) { return q.det > 0.0 && std::isfinite(q.det); }) &&
        (in.fans.empty() || count_boundary_violations(in.fans, x) == 0);
    if (!start_valid) {
        StageRecord& record =
            result.stages.add(Stage::kVertexStage, VertexStageOutcome::kSkippedInfeasibleStart);
        record.figures = std::to_string(start.inverted) + " inverted simplices";
        if (!in.fans.empty())
            record.figures += ", " + std::to_string(count_boundary_violations(in.fans, x)) +
                              " boundary angle sums of 2 pi or more";
        result.positions = prepared.to_original(x);
        return;
    }
    const std::vector<unsigned char> fixed = vertex_stage_fixed(prepared);
    auto largest_distortion = [&](const Eigen::MatrixXd& positions) {
        double largest = 0.0;
        if (prepared.energy == nullptr) return largest;
        for (const Mat<D>& A : linear_parts<D>(prepared.mesh, prepared.frames, positions))
            largest = std::max(largest, prepared.energy->barrier_distortion(A));
        return largest;
    };

    // Each round is a run of the vertex stage at one bound, with E_C's exponent continuation
    // (vertex_stage.h): its rounds raise s to options.s; a run that left degenerate simplices
    // where its start had none was undone there, and ends the descent.
    bool undone = false;
    auto run_round = [&](double bound) {
        const ExponentContinuation<D> continuation = exponent_continuation<D>(prepared, {}, bound);
        char line[200];
        std::snprintf(line, sizeof line,
                      "vertex descent round %d: bound %.4g, largest distortion %.4g",
                      int(result.descent_rounds.size()), bound, largest_distortion(x));
        log_line(observer.logger, line);
        SimplexAssemblyOptions o = with_time_left(options, budget);
        o.bound = bound;
        const VertexStage v = run_vertex_stage<D>(
            prepared.mesh, prepared.frames, prepared.topology,
            continuation.energies ? continuation.energies(options.s) : in.energies, x, fixed, o,
            observer.logger,
            VertexStageTerms<D>{in.fans, in.constraints, in.plugins, in.plugin_stage,
                                continuation});
        for (const ContinuationRound& r : v.rounds) {
            result.descent_rounds.push_back(r);
            undone |= r.outcome == VertexStageOutcome::kRanUndone;
        }
        if (v.ran()) {
            x = v.positions;
            result.vertex_stage = v.newton;
        }
        record_vertex_stage(result.stages, v, v.newton.times.total);
        return largest_distortion(x);
    };

    // The exponent's continuation, bounded from the start when the start is within K; then the
    // bound's continuation (bound_rounds.h) for a start that was over it.
    const double first_bound = largest_distortion(x) < options.bound ? options.bound : kInfinity;
    const double after = run_round(first_bound);
    if (!undone && prepared.energy != nullptr) {
        const RoundedBound rounded{
            .target = options.bound,
            .identity = prepared.energy->barrier_distortion(Mat<D>::Identity())};
        run_bound_rounds(kDescentBoundRule, {rounded}, {first_bound}, {after}, budget,
                         [&](const std::vector<double>& bounds) {
                             const double reached = run_round(bounds[0]);
                             if (undone) return std::optional<std::vector<double>>();
                             return std::optional(std::vector<double>{reached});
                         });
    }
    result.times.vertex_stage += stage.lap();
    result.newton.num_threads = result.vertex_stage.num_threads;  // no assembly ran
    result.positions = prepared.to_original(x);
}

std::string describe_descent(const SimplexAssemblyResult& result) {
    std::ostringstream message;
    const std::vector<ContinuationRound>& rounds = result.descent_rounds;
    if (!descent_started(result)) {
        // The first vertex stage is the descent's (the fallback may have run more).
        const auto skipped =
            std::find_if(result.stages.records.begin(), result.stages.records.end(),
                         [](const StageRecord& r) { return r.stage == Stage::kVertexStage; });
        message << "The start is not valid ("
                << (skipped != result.stages.records.end() ? skipped->figures : "not run")
                << "): no descent ran";
        return message.str();
    }
    int steps = 0;
    for (const ContinuationRound& r : rounds) steps += r.iterations;
    message << "Newton on the vertex positions from the valid start: " << rounds.size() << " round"
            << (rounds.size() == 1 ? "" : "s") << ", " << steps << " iterations";
    if (!rounds.empty()) {
        const ContinuationRound& last = rounds.back();
        message << ", s " << rounds.front().s << " to " << last.s << " ("
                << (newton_ran(last.outcome) ? to_string(result.vertex_stage.termination)
                                             : to_string(last.outcome));
        if (last.undone_degenerate > 0)
            message << "; undone: it left " << last.undone_degenerate
                    << " degenerate simplices, its start none";
        message << ")";
    }
    if (!result.verification.within_bound()) {
        message << "; the bound " << result.verification.bound
                << " was not reached (largest distortion " << result.verification.max_distortion
                << ")";
    }
    return message.str();
}

template void solve_descent<2>(const PreparedProblem<2>&, const SimplexAssemblyOptions&,
                               const TimeBudget&, const SimplexAssemblyObserver&,
                               SimplexAssemblyResult&);
template void solve_descent<3>(const PreparedProblem<3>&, const SimplexAssemblyOptions&,
                               const TimeBudget&, const SimplexAssemblyObserver&,
                               SimplexAssemblyResult&);

}  // namespace sa
