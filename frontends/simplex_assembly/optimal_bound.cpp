#include "frontends/simplex_assembly/optimal_bound.h"

#include <memory>
#include <string>

#include "energies/distortion.h"
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

/// Largest distortions within this share of the identity's are the identity's: computed from
/// positions, a map that is a similarity on every simplex gives 1 + a few ulps, not 1.
constexpr double kIdentityRoundOff = 1e-9;

/// Whether a round that took a largest distortion from `before` to `after` lowered it: by more
/// than `tolerance` of its distance before to `identity` (the distortion of a similarity or a
/// rotation, where every measure bounded here is least: 1 for conformal K) and by more than the
/// rounds' `margin` of it (gains under the slack each next bound gets are not progress). Relative
/// to K alone, a round that lowers K - 1 from 3.5e-4 to 2.6e-4 counted as no progress.
bool lowered(double before, double after, double identity, double tolerance, double margin) {
    const double distance = before - identity > 0.0 ? before - identity : before;
    const double gain = before - after;
    return gain > tolerance * distance && gain > margin * before;
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
    if (!(rounds.margin >= 0.0 && rounds.margin < 1.0)) {
        throw InvalidArgumentError("optimal bound: margin = " + std::to_string(rounds.margin) +
                                   ": must be in [0, 1)");
    }
    if (!(rounds.tolerance >= 0.0 && rounds.tolerance < 1.0)) {
        throw InvalidArgumentError("optimal bound: tolerance = " +
                                   std::to_string(rounds.tolerance) + ": must be in [0, 1)");
    }
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
    // The distortion of the identity in each bound's measure (lowered()).
    double builtin_identity = 0.0;
    if (options.builtin_energy) {
        const Mat<D> I = Mat<D>::Identity();
        builtin_identity =
            distortion<D>(options.distortion, matrix_invariants<D>(I, true), options.gamma);
    }
    std::vector<double> own_identity;
    for (const auto& energy : problem.energies) {
        if (!bounds_a_distortion(*energy)) continue;
        own_identity.push_back(static_cast<const SimplexTerm<D>&>(*energy).max_distortion(
            std::vector<Mat<D>>{Mat<D>::Identity()}));
    }
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
            // A largest distortion at the identity's (the map a similarity, or a rotation, on
            // every simplex), to round-off, is the least any map has: its bound stays, as no
            // bound can be below it and one a few ulps above leaves the barrier no room. When
            // every one is there, the bound is optimal and the rounds end.
            const auto above_identity = [](double K, double identity) {
                return K > identity * (1.0 + kIdentityRoundOff);
            };
            std::string bounds;
            bool lowerable = false;
            if (options.builtin_energy) {
                const double K = previous.max_distortion * (1.0 + rounds.margin);
                if (above_identity(K, builtin_identity)) {
                    options.bound = K;
                    bounds = "K = " + std::to_string(K);
                    lowerable = true;
                }
            }
            std::size_t k = 0;
            for (auto& energy : problem.energies) {
                // previous.bounds lists the barriers on a distortion in the problem's order.
                if (!bounds_a_distortion(*energy) || k >= previous.bounds.size()) continue;
                const double K = previous.bounds[k].max_distortion * (1.0 + rounds.margin);
                if (above_identity(K, own_identity[k])) {
                    energy = with_bound(*energy, K);
                    bounds +=
                        (bounds.empty() ? "" : ", ") + energy->name() + " K = " + std::to_string(K);
                    lowerable = true;
                }
                ++k;
            }
            if (!lowerable) {
                log_line(observer.logger,
                         "optimal bound: every largest distortion is the identity's, the least");
                break;
            }
            log_line(observer.logger,
                     "optimal bound: round " + std::to_string(round) + ", " + bounds);
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
            if (options.builtin_energy) {
                improved |= lowered(previous.max_distortion, r.verification.max_distortion,
                                    builtin_identity, rounds.tolerance, rounds.margin);
            }
            for (std::size_t k = 0; k < r.verification.bounds.size(); ++k) {
                improved |= k < previous.bounds.size() && k < own_identity.size() &&
                            lowered(previous.bounds[k].max_distortion,
                                    r.verification.bounds[k].max_distortion, own_identity[k],
                                    rounds.tolerance, rounds.margin);
            }
        }
        result.solve = std::move(r);
        result.verified = true;
        kept_in_part = restarted && D == 2;
        if (kept_in_part) {
            kept_options = round_options;
            kept_problem.initial = problem.initial;
            kept_problem.energies = problem.energies;
        }
        if (!improved) break;
    }
    if (kept_in_part) {
        // The whole map, once, from its positions.
        Stopwatch watch;
        MappingProblem input = problem;
        input.initial = std::move(kept_problem.initial);
        input.energies = std::move(kept_problem.energies);
        SimplexAssemblyResult& r = result.solve;
        verify_result<D>(input, kept_options, r, &prepared->topology);
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
