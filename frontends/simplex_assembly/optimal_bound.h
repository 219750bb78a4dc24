#pragma once
// The optimal bound (the paper's 5.1, "Optimal bound"): rounds of the mesh driver, each starting
// from the previous round's verified result and taking its largest distortion (times 1 + margin)
// as the new bound, until a round lowers no bound by more than a share `tolerance` of its
// distance to the distortion of a similarity (K - 1 for conformal K), or does not verify: the
// bound loop of bound_rounds.h, each round a solve of the mesh driver.
//
// With OptimalBoundOptions::submesh_band > 0 the rounds after the first solve regions around the
// simplices within that band of the bound (the largest distortions), the rest of the map fixed.
//
// Every bound of the problem takes part, each lowered to its own largest distortion: the options'
// built-in barrier (options.bound, in options.distortion's measure; when builtin_energy is set)
// and every barrier on a distortion among the problem's own energies (MappingProblem::energies,
// SimplexTerm::with_bound): deformation's conformal and volumetric bounds together, a user's
// DistortionBarrier. The mapping energy E_m keeps measuring the change from problem.reference
// (when set) in every round. One loop for parameterization, deformation and PolyCube.

#include <functional>
#include <vector>

#include "frontends/simplex_assembly/bound_rounds.h"
#include "frontends/simplex_assembly/map_solve.h"

namespace sa {

struct BoundRound {
    double bound = kInfinity;     ///< K of the built-in barrier for this round
    double max_distortion = 0.0;  ///< of its result, in the built-in barrier's measure
    /// The problem's own barriers on a distortion: their bound this round and their largest
    /// distortion on its result.
    std::vector<BoundCheck> bounds;
    bool success = false;  ///< verified and within every bound
    int iterations = 0;    ///< assembly and vertex stage
    double time = 0.0;
};

struct OptimalBoundOptions {
    /// Rounds at most (>= 1; 1 = a single solve with the given bounds).
    int rounds = 10;
    /// A round must lower some bound K by more than this share of K - d_I to go on, d_I the
    /// distortion of the identity in K's measure (1 for conformal K: near K = 1 a share of K
    /// itself stopped rounds that still lowered K - 1 by a quarter), and by more than
    /// margin K.
    double tolerance = 1e-3;
    /// When > 0, the rounds after the first run in the submesh mode with this
    /// SimplexAssemblyOptions::submesh_band: they start from the previous verified map, where only
    /// the largest distortions need work, so each solves regions around the simplices within that
    /// band of the bound with the rest of the map fixed. The first round runs in options.mode
    /// (it may have folds to repair). 0: every round in options.mode.
    double submesh_band = 0.0;
    /// Each next bound is the largest distortion times 1 + margin (a round gaining less than
    /// that share of K does not go on). With 0 the simplex at the
    /// maximum starts at its bound, where the barrier is infinite, and the round disassembles;
    /// a small margin keeps the previous result a feasible start (the submesh mode's regions then
    /// go straight to the vertex stage, with the barrier at its steepest on that simplex).
    double margin = 0.0;
    /// A front-end's own check of a round's result beyond the driver's verification (PolyCube:
    /// verify_polycube() on its positions); a round it rejects counts as one that did not verify.
    std::function<bool(const SimplexAssemblyResult&)> accept;

    /// The rounds after the first as the bound loop takes them (bound_rounds.h).
    BoundRule rule() const {
        return BoundRule{.max_rounds = rounds - 1, .margin = margin, .tolerance = tolerance};
    }
};

struct OptimalBound {
    /// The last round that verified within its bounds, or the first round when none did.
    SimplexAssemblyResult solve;
    bool verified = false;  ///< some round verified within its bounds
    std::vector<BoundRound> rounds;
    MapQuality initial_quality;  ///< of the problem's initial map (the first round's)
};

/// Runs the rounds on `problem` (its initial map starts the first round) with `options`. The
/// submesh-mode rounds after the first keep the first round's prepared problem (topology,
/// normalization, frames: restart_problem() in prepared_problem.h) and change only its start and
/// bounds; each round's result is verified from its positions.
OptimalBound optimal_bound(MappingProblem problem, SimplexAssemblyOptions options,
                           const OptimalBoundOptions& rounds,
                           const SimplexAssemblyObserver& observer = {});

}  // namespace sa
