#pragma once
// The bound's continuation: the paper's optimal-bound rounds (section 5.1). A verified map is
// solved again with each bound K just above its largest distortion d, then again from that
// result, while the rounds lower d. The one bound loop: the mesh driver's optimal bound
// (optimal_bound.h: full or submesh solves, every bound of the problem lowered together) and the
// vertex descent from a valid start over its bound (detail/vertex_descent.h) both run it, each with
// its own round and its BoundRule.
//
// Each bound k of a problem has
//   d_k   its largest distortion on the last verified result,
//   I_k   the distortion of a similarity or rotation in its measure (the least any map has: 1 for
//         conformal K), and
//   T_k   its target: the bound the caller asked for (the descent), or I_k itself (the optimal
//         bound: as low as the rounds go).
// Before a round every bound gets
//   K_k kept        when d_k <= I_k (1 + 1e-9): a map at the identity's distortion, to round-off
//                   (no bound is below it, and one a few ulps above leaves the barrier no room);
//   K_k = T_k       when d_k < T_k (reached: a round at the target);
//   K_k = d_k + margin d_k + headroom (d_k - I_k)   otherwise;
// and the rounds end when no bound changes, when a round lowers no d_k by more than
// tolerance (d_k - I_k) and margin d_k, when a round does not verify (the caller keeps the last
// one that did), after max_rounds rounds, or when the time budget runs out.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "optim/time_budget.h"

namespace sa {

struct BoundRule {
    int max_rounds = 10;  ///< rounds at most after the first solve
    /// Room above d in each next bound, as a share of d: with 0 the simplex at the maximum starts
    /// at its bound, where the barrier is infinite (a solve that disassembles does not mind); a
    /// small margin keeps the previous result a feasible start.
    double margin = 0.0;
    /// Room above d as a share of d - I: a start well inside the barrier, for a solve in vertex
    /// variables that must move the simplex at the maximum first.
    double headroom = 0.0;
    /// A round must lower some d by more than this share of d - I to go on (near the identity a
    /// share of d itself stops rounds that still lower d - I by a quarter), and by more than
    /// margin d (gains under the room each next bound gets are not progress).
    double tolerance = 1e-3;

    /// The next bound above a largest distortion `largest` whose measure's identity is `identity`.
    double next_bound(double largest, double identity) const;
    /// Whether a round that took a largest distortion from `before` to `after` lowered it.
    bool lowered(double before, double after, double identity) const;
    /// Throws InvalidArgumentError naming `context` and the field when one is out of range.
    void validate(const std::string& context) const;
};

/// One bound of the problem: the target and identity it is lowered towards.
struct RoundedBound {
    double target = 0.0;    ///< T: the bound asked for, or `identity` for the optimal bound
    double identity = 1.0;  ///< I: the distortion of a similarity in its measure
};

enum class BoundRoundsEnd {
    kAtTarget,     ///< no bound changes: each reached its target or the identity's distortion
    kNoProgress,   ///< a round lowered no largest distortion enough (BoundRule::lowered)
    kRoundFailed,  ///< a round did not verify; the one before is kept
    kRoundLimit,   ///< max_rounds rounds ran
    kTimeLimit,    ///< the time budget ran out
};

std::string to_string(BoundRoundsEnd end);

/// A round: solves with these bounds (one per RoundedBound, in order) from the last verified
/// result and returns the largest distortions of its own result, or nothing when it did not
/// verify within them.
using BoundRoundSolve =
    std::function<std::optional<std::vector<double>>(const std::vector<double>&)>;

/// Runs the rounds after a first solve that ran at `bounds` and reached `largest` (one of each per
/// entry of `rounded`). `round` is called with each round's bounds.
BoundRoundsEnd run_bound_rounds(const BoundRule& rule, const std::vector<RoundedBound>& rounded,
                                std::vector<double> bounds, std::vector<double> largest,
                                const TimeBudget& budget, const BoundRoundSolve& round);

}  // namespace sa
