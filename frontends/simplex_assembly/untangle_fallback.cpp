#include "frontends/simplex_assembly/detail/untangle_fallback.h"

#include "frontends/simplex_assembly/detail/forced_distortion.h"
#include "frontends/simplex_assembly/detail/vertex_stage.h"
#include "frontends/simplex_assembly/map_rank.h"
#include "geometry/quality/local_injectivity.h"
#include "geometry/quality/map_quality.h"
#include "optim/stopwatch.h"

namespace sa {

namespace {

/// Inverted and degenerate simplices of `positions` (normalized), by map_quality()'s rule, and
/// the stars of its wraps (local_injectivity.h).
template <int D>
Index invalid_simplices(const PreparedProblem<D>& p, const Eigen::MatrixXd& positions) {
    const std::vector<Mat<D>> A = linear_parts<D>(p.mesh, p.frames, positions);
    const MapQuality q = map_quality<D>(A, p.frames.volume);
    return q.inverted + q.degenerate +
           static_cast<Index>(
               wrapped_simplices<D>(p.mesh, p.topology, p.frames, A, &p.tet_edges).size());
}

}  // namespace

template <int D>
UntangleResult untangle_prepared(PreparedProblem<D>& p, const SimplexAssemblyOptions& options,
                                 const TimeBudget& budget, const Eigen::MatrixXd& start,
                                 const Logger& logger) {
    UntangleOptions o;
    o.until_valid = true;
    if (!options.until_valid) {
        o.accept = [&p](const Eigen::MatrixXd& x) {
            return simplices_beyond_barrier_cap<D>(p, x) == 0;
        };
    }
    o.max_time_seconds = with_time_left(options, budget).max_time_seconds;
    o.projection = options.projection;
    o.projection_epsilon = options.projection_epsilon;
    o.linear_solver = options.linear_solver;
    o.num_threads = options.num_threads;
    return untangle<D>(p.mesh, p.frames, start, vertex_stage_fixed(p), o, logger);
}

template <int D>
bool untangle_fallback(PreparedProblem<D>& p, const SimplexAssemblyOptions& options,
                       const TimeBudget& budget, const SimplexAssemblyObserver& observer,
                       SimplexAssemblyResult& result) {
    if (budget.exhausted() || !p.assembly.fans.empty()) return false;  // no E_theta here
    Stopwatch watch;
    const MappingProblem& input = *p.input;
    Eigen::MatrixXd initial = p.start;
    for (std::size_t k = 0; k < input.handles.size(); ++k)
        initial.row(input.handles[k]) = p.assembly.targets[k].transpose();
    const Eigen::MatrixXd reached = (result.positions.rowwise() - p.map_center) * p.scale;
    const Index before = invalid_simplices<D>(p, reached);
    const bool from_result =
        !MapRank{invalid_simplices<D>(p, initial)}.better_than(MapRank{before});
    log_line(observer.logger,
             std::string("no valid map: untangling in vertex variables from the ") +
                 (from_result ? "result" : "initial map"));
    const UntangleResult u =
        untangle_prepared<D>(p, options, budget, from_result ? reached : initial, observer.logger);
    Eigen::MatrixXd positions = u.positions;
    const Index after = invalid_simplices<D>(p, positions);
    const bool replaced = MapRank{after}.better_than(MapRank{before});
    StageRecord record{
        .stage = Stage::kFallback,
        .outcome = replaced ? FallbackOutcome::kReplaced : FallbackOutcome::kNoBetter,
        .newton_steps = u.iterations};
    if (u.iterations > 0) record.termination = u.newton.termination;
    record.figures = "from the " + std::string(from_result ? "result" : "initial map") + ", " +
                     std::to_string(u.iterations) + " Newton steps, " + to_string(u.outcome) +
                     (u.untangled ? "" : ": " + to_string(u.stop)) + ", " + std::to_string(after) +
                     " bad simplices against " + std::to_string(before);
    record.seconds = watch.lap();
    result.stages.records.push_back(record);
    if (!replaced) return false;
    result.times.optimization += record.seconds;
    if (u.untangled && options.vertex_stage && !options.until_valid && budget.exhausted()) {
        result.stages.add(Stage::kVertexStage, VertexStageOutcome::kSkippedTimeLimit);
    } else if (u.untangled && options.vertex_stage && !options.until_valid) {
        const VertexStage vertex = run_vertex_stage<D>(
            p.mesh, p.frames, p.topology, p.assembly.energies, positions, vertex_stage_fixed(p),
            with_time_left(options, budget), observer.logger,
            VertexStageTerms<D>{{}, p.assembly.constraints, {}, {}, exponent_continuation<D>(p)});
        if (vertex.ran()) {
            positions = vertex.positions;
            result.vertex_stage = vertex.newton;
        }
        const double seconds = watch.lap();
        result.times.vertex_stage += seconds;
        record_vertex_stage(result.stages, vertex, seconds);
    }
    result.positions = p.to_original(positions);
    return true;
}

template UntangleResult untangle_prepared<2>(PreparedProblem<2>&, const SimplexAssemblyOptions&,
                                             const TimeBudget&, const Eigen::MatrixXd&,
                                             const Logger&);
template UntangleResult untangle_prepared<3>(PreparedProblem<3>&, const SimplexAssemblyOptions&,
                                             const TimeBudget&, const Eigen::MatrixXd&,
                                             const Logger&);
template bool untangle_fallback<2>(PreparedProblem<2>&, const SimplexAssemblyOptions&,
                                   const TimeBudget&, const SimplexAssemblyObserver&,
                                   SimplexAssemblyResult&);
template bool untangle_fallback<3>(PreparedProblem<3>&, const SimplexAssemblyOptions&,
                                   const TimeBudget&, const SimplexAssemblyObserver&,
                                   SimplexAssemblyResult&);

}  // namespace sa
