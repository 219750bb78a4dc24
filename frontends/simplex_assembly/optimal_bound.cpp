#include "frontends/simplex_assembly/optimal_bound.h"

#include <memory>
#include <optional>
#include <string>

#include "energies/distortion.h"
#include "frontends/simplex_assembly/bound_rounds.h"
#include "frontends/simplex_assembly/detail/prepared_problem.h"
#include "frontends/simplex_assembly/detail/round_verification.h"

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

template <int D>
OptimalBound run_rounds(MappingProblem problem, SimplexAssemblyOptions options,
                        const OptimalBoundOptions& rounds, const SimplexAssemblyObserver& observer);

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
    rounds.rule().validate("optimal bound");
    if (problem.mesh.simplex_dimension() == 3)
        return run_rounds<3>(std::move(problem), std::move(options), rounds, observer);
    return run_rounds<2>(std::move(problem), std::move(options), rounds, observer);
}

namespace {

template <int D>
OptimalBound run_rounds(MappingProblem problem, SimplexAssemblyOptions options,
                        const OptimalBoundOptions& rounds,
                        const SimplexAssemblyObserver& observer) {
    const TimeBudget budget(options.max_time_seconds);
    OptimalBound result;
    // The problem prepared for the first round (topology, normalization, frames, anchors): the
    // submesh rounds restart it from each verified result with the new bounds (restart_problem);
    // a full-mode round prepares the problem again (it needs the disassembly of its start).
    std::unique_ptr<PreparedProblem<D>> prepared;
    // The restarted rounds move the vertices of their regions only: each is verified where it
    // moved (round_verification.h), and the map kept is verified whole at the end, with the
    // bounds and start of its round.
    VerifiedMap changes;
    bool kept_in_part = false;
    SimplexAssemblyOptions kept_options;
    MappingProblem kept_problem;
    // The bounds lowered (bound_rounds.h), in the order of Verification's: the built-in barrier's
    // (when builtin_energy is set), then each of the problem's own barriers on a distortion. Each
    // is lowered towards the distortion of the identity in its measure.
    std::vector<RoundedBound> rounded;
    if (options.builtin_energy) {
        const Mat<D> I = Mat<D>::Identity();
        const double identity =
            distortion<D>(options.distortion, matrix_invariants<D>(I, true), options.gamma);
        rounded.push_back({.target = identity, .identity = identity});
    }
    std::vector<std::size_t> own;  // the index in problem.energies of each own bound
    for (std::size_t e = 0; e < problem.energies.size(); ++e) {
        if (!bounds_a_distortion(*problem.energies[e])) continue;
        own.push_back(e);
        const double identity = static_cast<const SimplexTerm<D>&>(*problem.energies[e])
                                    .max_distortion(std::vector<Mat<D>>{Mat<D>::Identity()});
        rounded.push_back({.target = identity, .identity = identity});
    }
    const std::size_t first_own = options.builtin_energy ? 1 : 0;
    auto largest_of = [&](const Verification& v) {
        std::vector<double> largest;
        if (options.builtin_energy) largest.push_back(v.max_distortion);
        for (std::size_t k = 0; k < own.size(); ++k)
            largest.push_back(k < v.bounds.size() ? v.bounds[k].max_distortion : 0.0);
        return largest;
    };
    // The bounds of the last round (empty before the first: the problem's own).
    std::vector<double> in_use;

    // One round with `bounds` (empty: the problem's own) from problem.initial.
    auto solve_round =
        [&](const std::vector<double>& bounds) -> std::optional<std::vector<double>> {
        Stopwatch round_watch;
        const bool first = result.rounds.empty();
        if (!first) {
            // The previous verified result starts this round, with the new bounds.
            problem.initial = result.solve.positions;
            if (rounds.submesh_band > 0.0) {
                options.mode = SolveMode::kSubmesh;
                options.submesh_band = rounds.submesh_band;
            }
            std::string described;
            if (options.builtin_energy && bounds[0] != in_use[0]) {
                options.bound = bounds[0];
                described = "K = " + std::to_string(bounds[0]);
            }
            for (std::size_t k = 0; k < own.size(); ++k) {
                const double K = bounds[first_own + k];
                if (K == in_use[first_own + k]) continue;
                auto& energy = problem.energies[own[k]];
                energy = with_bound(*energy, K);
                described +=
                    (described.empty() ? "" : ", ") + energy->name() + " K = " + std::to_string(K);
            }
            log_line(observer.logger, "optimal bound: round " +
                                          std::to_string(result.rounds.size()) + ", " + described);
        }
        const SimplexAssemblyOptions round_options = with_time_left(options, budget);
        round_options.validate();
        Stopwatch prepare_watch;
        StageTimes times;
        const bool restarted = prepared && options.mode == SolveMode::kSubmesh;
        if (restarted) {
            restart_problem<D>(*prepared, round_options, times);
        } else {
            prepared = prepare_problem<D>(problem, round_options, times);
            changes = VerifiedMap{};
        }
        times.total = prepare_watch.seconds();
        SimplexAssemblyResult r = solve_prepared<D>(*prepared, round_options, observer, times,
                                                    restarted && D == 2 ? &changes : nullptr);
        if (first) result.initial_quality = r.initial_quality;
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
            return std::nullopt;  // the last verified round is kept
        }
        result.solve = std::move(r);
        result.verified = true;
        if (!first) in_use = bounds;
        kept_in_part = restarted && D == 2;
        if (kept_in_part) {
            kept_options = round_options;
            kept_problem.initial = problem.initial;
            kept_problem.energies = problem.energies;
        }
        return largest_of(result.solve.verification);
    };

    if (solve_round({})) {
        const Verification& first = result.solve.verification;
        if (options.builtin_energy) in_use.push_back(options.bound);
        for (std::size_t k = 0; k < own.size(); ++k)
            in_use.push_back(k < first.bounds.size() ? first.bounds[k].bound : kInfinity);
        const BoundRoundsEnd end = run_bound_rounds(rounds.rule(), rounded, in_use,
                                                    largest_of(first), budget, solve_round);
        if (rounds.rounds > 1) {
            log_line(observer.logger, "optimal bound: " + std::to_string(result.rounds.size()) +
                                          " round" + (result.rounds.size() == 1 ? "" : "s") +
                                          ", ended: " + to_string(end));
        }
    }
    if (kept_in_part) {
        // The whole map, once, from its positions.
        Stopwatch watch;
        MappingProblem input = problem;
        input.initial = std::move(kept_problem.initial);
        input.energies = std::move(kept_problem.energies);
        SimplexAssemblyResult& r = result.solve;
        verify_result<D>(input, kept_options, r, &prepared->topology);
        r.valid = r.success;
        r.success =
            r.success && r.verification.within_bound() && (!rounds.accept || rounds.accept(r));
        r.times.verification += watch.seconds();
        if (!r.success) {
            result.verified = false;
            r.message = "FAILED: " + r.verification.describe() +
                        " (the whole map after its rounds, each verified where it moved)";
        }
        log_line(observer.logger,
                 "optimal bound: the map kept, verified whole: " + r.verification.describe());
    }
    return result;
}

}  // namespace

}  // namespace sa
