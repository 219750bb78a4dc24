#pragma once
// The one rule for choosing among candidate maps: starts tried one after the other, a fallback's
// result against the result it may replace, an untangled map against the map it came from.
// A candidate replaces the map it competes with when it has fewer failing simplices (inverted,
// degenerate, or whatever keeps the next stage from starting: over a bound, beyond the barrier's
// exponent cap; or 1 for a map that did not verify, when only the verdict is known), or when
// both have none and its largest distortion is lower. An equal rank keeps the incumbent.
// Used by the untangling fallback (untangle_fallback.h), the submesh mode's start
// (submesh_start.h: at an equal count a later local/global iterate, lower in its energy,
// replaces an earlier one) and sa param's starts and fallback (frontends/param/).

#include "optim/types.h"

namespace sa {

struct MapRank {
    /// Simplices that keep the map from being valid (0: it verifies, or is a valid start).
    Index failing = 0;
    /// Its largest distortion, compared only between maps with no failing simplex.
    double max_distortion = kInfinity;

    /// The rank of a map known only by its verdict and largest distortion.
    static MapRank of_verdict(bool verified, double max_distortion) {
        return MapRank{verified ? 0 : 1, max_distortion};
    }

    /// Whether this candidate should replace `incumbent`.
    bool better_than(const MapRank& incumbent) const {
        if (failing != incumbent.failing) return failing < incumbent.failing;
        return failing == 0 && max_distortion < incumbent.max_distortion;
    }
};

}  // namespace sa
