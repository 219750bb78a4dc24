#include "frontends/param/start_fallback.h"

#include <optional>
#include <sstream>

#include "geometry/initial_maps.h"
#include "geometry/map_quality.h"
#include "optim/stopwatch.h"
#include "optim/time_budget.h"

namespace sa {

namespace {

MapQuality start_quality(const SimplicialMesh& mesh, const Eigen::MatrixXd& uv) {
    const RestFrames<2> frames = rest_frames<2>(mesh);
    return map_quality<2>(linear_parts<2>(mesh, frames, uv), frames.volume);
}

}  // namespace

StartFallback fall_back_to_tutte(const MappingProblem& problem, const StartDisk& disk,
                                 const SimplexAssemblyOptions& solver,
                                 const SimplexAssemblyObserver& observer, std::string reason) {
    Stopwatch watch;
    const TimeBudget budget(solver.max_time_seconds);
    StartFallback fallback;
    fallback.used = true;
    fallback.reason = std::move(reason);
    log_line(observer.logger, "fallback: " + fallback.reason);
    for (TutteWeights weights : {TutteWeights::kMeanValue, TutteWeights::kUniform}) {
        TriedStart tried;
        tried.name = weights == TutteWeights::kMeanValue ? "tutte" : "tutte-uniform";
        MappingProblem start = problem;
        start.initial = disk.to_surface(tutte_embedding(disk.mesh, disk.topology, weights));
        log_line(observer.logger, "fallback: start from " + tried.name);
        std::ostringstream outcome;
        std::optional<VertexDescentResult> repaired;
        const MapQuality quality = start_quality(problem.mesh, start.initial);
        if (quality.degenerate > 0 && quality.inverted == 0) {
            // Positively oriented but numerically degenerate (a nearly closed surface shrunk
            // toward one point): repaired by the isometric barrier, which, unlike the conformal
            // one, grows shrunken triangles back; E_m is left out (its reference is the shrunken
            // map itself).
            SimplexAssemblyOptions repair = with_time_left(solver, budget);
            repair.distortion = DistortionType::kIsometric;
            repair.bound = kInfinity;
            repair.mapping_distortion.reset();
            MappingProblem shrunken = start;
            shrunken.reference.resize(0, 0);
            const VertexDescentResult r = run_vertex_descent(shrunken, repair, observer);
            outcome << "its map had " << quality.degenerate
                    << " degenerate triangles; the isometric repair ";
            if (r.solve.success) {
                outcome << "removed them in " << r.rounds.size() << " rounds; ";
                start.initial = r.solve.positions;
                repaired = r;
            } else {
                outcome << "left " << r.solve.verification.degenerate << " degenerate and "
                        << r.solve.verification.inverted << " inverted; ";
            }
        }
        start.reference = start.initial;
        VertexDescentResult r = run_vertex_descent(start, with_time_left(solver, budget), observer);
        if (!r.solve.success && repaired && r.start_valid) {
            // The solver's energy shrank the repaired map back to degenerate triangles (its
            // minimizers are not representable: a conformal map of a deep tube shrinks
            // exponentially): the repaired map itself is the valid result.
            outcome << "the solver's energy from it left " << r.solve.verification.degenerate
                    << " degenerate triangles, so the repaired map is kept; ";
            r = std::move(*repaired);
        }
        tried.valid = r.start_valid;
        tried.verified = r.solve.success;
        tried.max_distortion = r.solve.verification.max_distortion;
        if (!r.start_valid) {
            outcome << "rejected: the map itself has " << r.solve.initial_quality.inverted
                    << " inverted and " << r.solve.initial_quality.degenerate
                    << " degenerate triangles";
        } else {
            outcome << r.solve.message;
        }
        tried.outcome = outcome.str();
        log_line(observer.logger, "fallback: " + tried.name + ": " + tried.outcome);
        const bool better =
            tried.verified && (!fallback.verified() ||
                               tried.max_distortion < fallback.solve.verification.max_distortion);
        fallback.starts.push_back(tried);
        if (better) {
            fallback.start = tried.name;
            fallback.initial_uv = start.initial;
            fallback.rounds = std::move(r.rounds);
            fallback.solve = std::move(r.solve);
        }
        if (fallback.verified() && fallback.solve.verification.within_bound()) break;
        if (budget.exhausted()) break;
    }
    fallback.time = watch.seconds();
    return fallback;
}

}  // namespace sa
