#include "frontends/simplex_assembly/bound_rounds.h"

#include <cstddef>

#include "optim/errors.h"

namespace sa {

namespace {

/// Largest distortions within this share of the identity's are the identity's: computed from
/// positions, a map that is a similarity on every simplex gives 1 + a few ulps, not 1.
constexpr double kIdentityRoundOff = 1e-9;

bool at_identity(double largest, double identity) {
    return !(largest > identity * (1.0 + kIdentityRoundOff));
}

}  // namespace

double BoundRule::next_bound(double largest, double identity) const {
    return largest + margin * largest + headroom * (largest - identity);
}

bool BoundRule::lowered(double before, double after, double identity) const {
    const double distance = before - identity > 0.0 ? before - identity : before;
    const double gain = before - after;
    return gain > tolerance * distance && gain > margin * before;
}

void BoundRule::validate(const std::string& context) const {
    auto check = [&](bool ok, const char* name, double value) {
        if (!ok) {
            throw InvalidArgumentError(context + ": " + name + " = " + std::to_string(value) +
                                       ": must be in [0, 1)");
        }
    };
    if (max_rounds < 0) {
        throw InvalidArgumentError(context + ": rounds = " + std::to_string(max_rounds) +
                                   ": must be >= 0");
    }
    check(margin >= 0.0 && margin < 1.0, "margin", margin);
    check(headroom >= 0.0 && headroom < 1.0, "headroom", headroom);
    check(tolerance >= 0.0 && tolerance < 1.0, "tolerance", tolerance);
}

std::string to_string(BoundRoundsEnd end) {
    switch (end) {
        case BoundRoundsEnd::kAtTarget:
            return "every bound at its target or the identity's distortion";
        case BoundRoundsEnd::kNoProgress:
            return "a round lowered no largest distortion";
        case BoundRoundsEnd::kRoundFailed:
            return "a round did not verify";
        case BoundRoundsEnd::kRoundLimit:
            return "round limit";
        case BoundRoundsEnd::kTimeLimit:
            return "time limit";
    }
    return "unknown";
}

BoundRoundsEnd run_bound_rounds(const BoundRule& rule, const std::vector<RoundedBound>& rounded,
                                std::vector<double> bounds, std::vector<double> largest,
                                const TimeBudget& budget, const BoundRoundSolve& round) {
    if (bounds.size() != rounded.size() || largest.size() != rounded.size()) {
        throw InvalidArgumentError("bound rounds: " + std::to_string(rounded.size()) +
                                   " bounds, but " + std::to_string(bounds.size()) +
                                   " start bounds and " + std::to_string(largest.size()) +
                                   " largest distortions");
    }
    for (int r = 0; r < rule.max_rounds; ++r) {
        std::vector<double> next = bounds;
        for (std::size_t k = 0; k < rounded.size(); ++k) {
            const RoundedBound& b = rounded[k];
            if (at_identity(largest[k], b.identity)) continue;
            next[k] = largest[k] < b.target ? b.target : rule.next_bound(largest[k], b.identity);
        }
        if (next == bounds) return BoundRoundsEnd::kAtTarget;
        if (budget.exhausted()) return BoundRoundsEnd::kTimeLimit;
        const std::optional<std::vector<double>> after = round(next);
        if (!after) return BoundRoundsEnd::kRoundFailed;
        // Without progress the rounds end, but a bound that has just come under its target
        // still gets its round at the target, and one that had it is where it was asked to be.
        bool progress = false;
        bool target_due = false;
        bool settled = true;
        for (std::size_t k = 0; k < rounded.size(); ++k) {
            const RoundedBound& b = rounded[k];
            const bool at_target = next[k] == b.target || at_identity((*after)[k], b.identity);
            if (!at_identity(largest[k], b.identity))
                progress |= rule.lowered(largest[k], (*after)[k], b.identity);
            target_due |= !at_target && (*after)[k] < b.target;
            settled &= at_target;
        }
        bounds = std::move(next);
        largest = *after;
        if (!progress && !target_due)
            return settled ? BoundRoundsEnd::kAtTarget : BoundRoundsEnd::kNoProgress;
    }
    return BoundRoundsEnd::kRoundLimit;
}

}  // namespace sa
