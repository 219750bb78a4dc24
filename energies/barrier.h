#pragma once
// The barrier E_C of section 4.1.2 for one simplex, as a function of its distortion d (conformal,
// volumetric or isometric) and bound K:
//   bounded   (K < inf):  e^{s d} / (K - d)
//   unbounded (K = inf):  e^{s d}
// The caller returns +inf before calling it when det A <= 0 or d >= K. s defaults to 1.

#include "optim/types.h"

namespace sa {

struct BarrierOptions {
    double bound = kInfinity;  ///< K; must be > 1 (every distortion above is >= 1)
    double s = 1.0;            ///< the exponent's scale; > 0
};

template <class S>
S barrier(const S& d, const BarrierOptions& options) {
    using std::exp;
    const S e = exp(options.s * d);
    if (options.bound < kInfinity) return e / (options.bound - d);
    return e;
}

}  // namespace sa
