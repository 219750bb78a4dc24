#pragma once
// The rule of E_C's exponent continuation, for every solve that runs one: the mesh driver's
// vertex stage (frontends/simplex_assembly/detail/vertex_stage.h) and `sa hex`'s optimization
// (frontends/hex/hex_optimization.h). A barrier e^{s d} whose distortions d span d_max - d_min
// has per-element Hessians that span about e^{s (d_max - d_min)}: past a range, no regularization
// makes their sum factorizable, and Newton lowers the worst d by only about 1/s per step. So a
// round runs at the exponent continuation_exponent() gives, raised round by round as the spread
// falls, until it is the one asked for.

#include <algorithm>

namespace sa {

/// The worst element's barrier relative to the best one's, as a power of e, at the start of a
/// round. Measured on generated disks with sliver triangles (docs/measurements.md, "Robustness"):
/// ranges of 10 to 30 converge, 50 leaves the first factorization failing.
inline constexpr double kExponentRange = 20.0;
/// Rounds of a continuation at most.
inline constexpr int kContinuationRounds = 30;
/// A round that lowers what a continuation follows (the spread of distortions; in the descent's
/// bound rounds, the largest distortion's distance to the identity's) by less than this share
/// ends it: the next round would hardly differ.
inline constexpr double kContinuationStall = 0.01;

/// The exponent of a round asked to run at `s` whose distortions span `spread` (d_max - d_min):
/// s, or kExponentRange / spread when that is smaller.
inline double continuation_exponent(double s, double spread) {
    return spread > 0.0 ? std::min(s, kExponentRange / spread) : s;
}

}  // namespace sa
