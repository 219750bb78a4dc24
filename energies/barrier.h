#pragma once
// The barrier E_C of section 4.1.2 for one simplex, as a function of its distortion d (conformal,
// volumetric or isometric) and bound K:
//   bounded   (K < inf):  e^{s d} / (K - d)
//   unbounded (K = inf):  e^{s d}
// The caller returns +inf before calling it when det A <= 0 or d >= K. s defaults to 1.
//
// e^{s d} overflows a double at s d = 709.8, which the 3D conformal distortion reaches at
// sigma_max / sigma_min of about 53: a feasible simplex (det A > 0, d < K) would read as
// infeasible. When the data force such a simplex (a fixed boundary whose own triangles or
// tetrahedra are that distorted, as in the Locally Injective Mappings benchmark's hard class),
// no map would be feasible for the barrier. Above s d = kBarrierExponentCap the exponential is
// therefore continued by its second-order Taylor polynomial, e^c (1 + u + u^2 / 2) with
// u = s d - c: the same value, slope and curvature at c, convex and increasing, finite for every
// finite d. Below the cap nothing changes.

#include "optim/dual.h"
#include "optim/types.h"

namespace sa {

struct BarrierOptions {
    double bound = kInfinity;  ///< K; must be > 1 (every distortion above is >= 1)
    double s = 1.0;            ///< the exponent's scale; > 0
};

/// Where e^{s d} gives way to its quadratic continuation: e^500 = 1.4e217 leaves a factor of
/// 1e91 before a sum of such terms overflows.
constexpr double kBarrierExponentCap = 500.0;

template <class S>
S barrier(const S& d, const BarrierOptions& options) {
    using std::exp;
    const S t = options.s * d;
    const S u = t - kBarrierExponentCap;
    const S e = value_of(t) <= kBarrierExponentCap
                    ? S(exp(t))
                    : S(std::exp(kBarrierExponentCap) * (1.0 + u + 0.5 * u * u));
    if (options.bound < kInfinity) return e / (options.bound - d);
    return e;
}

}  // namespace sa
