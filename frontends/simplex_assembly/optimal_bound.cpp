#include "frontends/simplex_assembly/optimal_bound.h"

#include <string>

#include "optim/errors.h"
#include "optim/stopwatch.h"
#include "optim/time_budget.h"

namespace sa {

namespace {

bool bounds_a_distortion(const SimplexTermBase& energy) {
    if (energy.dimension() == 2)
        return static_cast<const SimplexTerm<2>&>(energy).bounds_a_distortion();
    return static_cast<const SimplexTerm<3>&>(energy).bounds_a_distortion();
}

/// `energy` (a SimplexTerm<2> or <3>) with bound K.
std::shared_ptr<const SimplexTermBase> with_bound(const SimplexTermBase& energy, double K) {
    if (energy.dimension() == 2) return static_cast<const SimplexTerm<2>&>(energy).with_bound(K);
    return static_cast<const SimplexTerm<3>&>(energy).with_bound(K);
}

}  // namespace

OptimalBound optimal_bound(MappingProblem problem, SimplexAssemblyOptions options,
                           const OptimalBoundOptions& rounds,
                           const SimplexAssemblyObserver& observer) {
    if (rounds.rounds < 1) {
        throw InvalidArgumentError("optimal bound: rounds = " + std::to_string(rounds.rounds) +
                                   ": must be >= 1");
    }
    if (!(rounds.submesh_band >= 0.0 && rounds.submesh_band < 1.0)) {
        throw InvalidArgumentError("optimal bound: submesh_band = " +
                                   std::to_string(rounds.submesh_band) + ": must be in [0, 1)");
    }
    if (!(rounds.margin >= 0.0 && rounds.margin < 1.0)) {
        throw InvalidArgumentError("optimal bound: margin = " + std::to_string(rounds.margin) +
                                   ": must be in [0, 1)");
    }
    if (!(rounds.tolerance >= 0.0 && rounds.tolerance < 1.0)) {
        throw InvalidArgumentError("optimal bound: tolerance = " +
                                   std::to_string(rounds.tolerance) + ": must be in [0, 1)");
    }
    const TimeBudget budget(options.max_time_seconds);
    OptimalBound result;
    for (int round = 0; round < rounds.rounds; ++round) {
        Stopwatch round_watch;
        if (round > 0) {
            if (budget.exhausted()) break;
            // The previous verified result starts this round; each of its largest distortions is
            // the new bound of its barrier.
            const Verification& previous = result.solve.verification;
            problem.initial = result.solve.positions;
            if (rounds.submesh_band > 0.0) {
                options.mode = SolveMode::kSubmesh;
                options.submesh_band = rounds.submesh_band;
            }
            std::string bounds;
            if (options.builtin_energy) {
                options.bound = previous.max_distortion * (1.0 + rounds.margin);
                bounds = "K = " + std::to_string(options.bound);
            }
            std::size_t k = 0;
            for (auto& energy : problem.energies) {
                // previous.bounds lists the barriers on a distortion in the problem's order.
                if (!bounds_a_distortion(*energy) || k >= previous.bounds.size()) continue;
                const double K = previous.bounds[k].max_distortion * (1.0 + rounds.margin);
                energy = with_bound(*energy, K);
                bounds +=
                    (bounds.empty() ? "" : ", ") + energy->name() + " K = " + std::to_string(K);
                ++k;
            }
            log_line(observer.logger,
                     "optimal bound: round " + std::to_string(round) + ", " + bounds);
        }
        SimplexAssemblyResult r =
            run_simplex_assembly(problem, with_time_left(options, budget), observer);
        if (round == 0) result.initial_quality = r.initial_quality;
        BoundRound record;
        record.bound = options.builtin_energy ? options.bound : kInfinity;
        record.max_distortion = r.verification.max_distortion;
        record.bounds = r.verification.bounds;
        record.success =
            r.success && r.verification.within_bound() && (!rounds.accept || rounds.accept(r));
        record.iterations = r.newton.num_steps() + r.vertex_stage.num_steps();
        record.time = round_watch.seconds();
        result.rounds.push_back(record);
        if (!record.success) {
            if (!result.verified) result.solve = std::move(r);
            break;  // keep the last verified round
        }
        bool improved = !result.verified;
        if (result.verified) {
            const Verification& previous = result.solve.verification;
            const double keep = 1.0 - rounds.tolerance;
            if (options.builtin_energy)
                improved |= r.verification.max_distortion < previous.max_distortion * keep;
            for (std::size_t k = 0; k < r.verification.bounds.size(); ++k) {
                improved |=
                    k < previous.bounds.size() && r.verification.bounds[k].max_distortion <
                                                      previous.bounds[k].max_distortion * keep;
            }
        }
        result.solve = std::move(r);
        result.verified = true;
        if (!improved) break;
    }
    return result;
}

}  // namespace sa
