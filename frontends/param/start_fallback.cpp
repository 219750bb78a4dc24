#include "frontends/param/start_fallback.h"

#include <optional>
#include <sstream>

#include "frontends/simplex_assembly/map_rank.h"
#include "geometry/maps/initial_maps.h"
#include "geometry/quality/map_quality.h"
#include "optim/enum_names.h"
#include "optim/stopwatch.h"
#include "optim/time_budget.h"

namespace sa {

namespace {

constexpr EnumName<FallbackReason> kFallbackReasonNames[] = {
    {FallbackReason::kNotVerified, "does not verify"},
    {FallbackReason::kOverTheBound, "over the bound"}};

constexpr EnumName<TriedStartOutcome> kTriedStartOutcomeNames[] = {
    {TriedStartOutcome::kRejected, "rejected"},
    {TriedStartOutcome::kVerified, "verified"},
    {TriedStartOutcome::kNotVerified, "not verified"},
    {TriedStartOutcome::kRepairKept, "the repaired start kept"}};

MapQuality start_quality(const SimplicialMesh& mesh, const Eigen::MatrixXd& uv) {
    const RestFrames<2> frames = rest_frames<2>(mesh);
    return map_quality<2>(linear_parts<2>(mesh, frames, uv), frames.volume);
}

}  // namespace

std::string start_name(TutteWeights weights) {
    return weights == TutteWeights::kMeanValue ? "tutte" : "tutte-uniform";
}

std::string to_string(FallbackReason reason) {
    return enum_name(kFallbackReasonNames, reason);
}

std::string to_string(TriedStartOutcome outcome) {
    return enum_name(kTriedStartOutcomeNames, outcome);
}

std::string TriedStart::describe() const {
    std::ostringstream out;
    if (repair_degenerate > 0) {
        out << "its map had " << repair_degenerate
            << " degenerate triangles; the isometric repair ";
        if (repaired) {
            out << "removed them in " << repair_rounds << " rounds; ";
        } else {
            out << "left " << repair.degenerate << " degenerate and " << repair.inverted
                << " inverted; ";
        }
    }
    switch (outcome) {
        case TriedStartOutcome::kRejected:
            out << "rejected: the map itself has " << start_inverted << " inverted and "
                << start_degenerate << " degenerate triangles";
            break;
        case TriedStartOutcome::kRepairKept:
            out << "the solver's energy from it left " << descent_verification.degenerate
                << " degenerate triangles, so the repaired map is kept; " << descent;
            break;
        case TriedStartOutcome::kVerified:
        case TriedStartOutcome::kNotVerified:
            out << descent;
            break;
    }
    return out.str();
}

std::string StartFallback::describe_reason() const {
    return "the " + requested_start + " start's result " +
           (reason == FallbackReason::kOverTheBound
                ? "is over the bound (largest distortion " +
                      std::to_string(requested.max_distortion) + " > " +
                      std::to_string(requested.bound) + ")"
                : "does not verify (" + std::to_string(requested.inverted) + " inverted, " +
                      std::to_string(requested.degenerate) + " degenerate)");
}

SimplexAssemblyOptions descent_options(SimplexAssemblyOptions solver) {
    solver.mode = SolveMode::kDescent;
    solver.untangle_fallback = false;
    return solver;
}

StartFallback fall_back_to_tutte(const MappingProblem& problem, const StartDisk& disk,
                                 const SimplexAssemblyOptions& solver,
                                 const SimplexAssemblyObserver& observer,
                                 std::string requested_start, const Verification& requested) {
    Stopwatch watch;
    const TimeBudget budget(solver.max_time_seconds);
    StartFallback fallback;
    fallback.used = true;
    fallback.reason =
        requested.passed() ? FallbackReason::kOverTheBound : FallbackReason::kNotVerified;
    fallback.requested_start = std::move(requested_start);
    fallback.requested = requested;
    log_line(observer.logger, "fallback: " + fallback.describe_reason());
    for (TutteWeights weights : {TutteWeights::kMeanValue, TutteWeights::kUniform}) {
        TriedStart tried;
        tried.weights = weights;
        MappingProblem start = problem;
        start.initial = disk.to_surface(tutte_embedding(disk.mesh, disk.topology, weights));
        log_line(observer.logger, "fallback: start from " + start_name(weights));
        std::optional<SimplexAssemblyResult> repaired;
        const MapQuality quality = start_quality(problem.mesh, start.initial);
        if (quality.degenerate > 0 && quality.inverted == 0) {
            // Positively oriented but numerically degenerate (a nearly closed surface shrunk
            // toward one point): repaired by the isometric barrier, which, unlike the conformal
            // one, grows shrunken triangles back; E_m is left out (its reference is the shrunken
            // map itself).
            SimplexAssemblyOptions repair = descent_options(with_time_left(solver, budget));
            repair.distortion = DistortionType::kIsometric;
            repair.bound = kInfinity;
            repair.mapping_distortion.reset();
            MappingProblem shrunken = start;
            shrunken.reference.resize(0, 0);
            SimplexAssemblyResult r = run_simplex_assembly(shrunken, repair, observer);
            tried.repair_degenerate = quality.degenerate;
            tried.repaired = r.valid;
            tried.repair_rounds = static_cast<int>(r.descent_rounds.size());
            tried.repair = r.verification;
            if (r.valid) {
                start.initial = r.positions;
                repaired = std::move(r);
            }
        }
        start.reference = start.initial;
        SimplexAssemblyResult r =
            run_simplex_assembly(start, descent_options(with_time_left(solver, budget)), observer);
        const bool start_valid = descent_started(r);
        tried.start_inverted = r.initial_quality.inverted;
        tried.start_degenerate = r.initial_quality.degenerate;
        tried.descent_verification = r.verification;
        tried.outcome = !start_valid ? TriedStartOutcome::kRejected
                        : r.valid    ? TriedStartOutcome::kVerified
                                     : TriedStartOutcome::kNotVerified;
        if (!r.valid && repaired && start_valid) {
            // The solver's energy shrank the repaired map back to degenerate triangles (its
            // minimizers are not representable: a conformal map of a deep tube shrinks
            // exponentially): the repaired map itself is the valid result.
            tried.outcome = TriedStartOutcome::kRepairKept;
            r = std::move(*repaired);
        }
        tried.descent = r.message;
        tried.valid = start_valid;
        tried.verified = r.valid;
        tried.max_distortion = r.verification.max_distortion;
        log_line(observer.logger, "fallback: " + start_name(weights) + ": " + tried.describe());
        const bool better =
            MapRank::of_verdict(tried.verified, tried.max_distortion)
                .better_than(MapRank::of_verdict(fallback.verified(),
                                                 fallback.solve.verification.max_distortion));
        fallback.starts.push_back(tried);
        if (better) {
            fallback.start = weights;
            fallback.initial_uv = start.initial;
            fallback.rounds = r.descent_rounds;
            fallback.solve = std::move(r);
        }
        if (fallback.verified() && fallback.solve.verification.within_bound()) break;
        if (budget.exhausted()) break;
    }
    fallback.time = watch.seconds();
    return fallback;
}

}  // namespace sa
