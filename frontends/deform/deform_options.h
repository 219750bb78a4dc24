#pragma once
// Options of deformation posing (the paper's 5.4): the start, the mapping energy, the two
// bounds. The solve they configure is Simplex Assembly (frontends/simplex_assembly/) with
//   E_m = mu sum_i |A_i - A_i^0|^2  (unit weights, as the paper; A_i^0 the ARAP start's linear
//                                    parts, before the disassembly projects them),
//   E_C = a barrier on the conformal distortion d^c with bound conformal_bound and one on the
//         volumetric distortion d^vol with bound volumetric_bound, both at once (section 3:
//         d^c = trace(A^T A) / (2 det A) in 2D, (|A|^2 |A^-1|^2 - 1) / 8 in 3D;
//         d^vol = (det A + 1 / det A) / 2; each is 1 at a rotation),
// and, with optimal_bound, the optimal-bound loop of 5.1 lowering both: each round takes the
// largest d^c and the largest d^vol reached as its next two bounds (just above them), the rounds
// after the first in the submesh mode around the simplices near a bound (optimal_bound.h).

#include "frontends/simplex_assembly/disassembly.h"
#include "geometry/maps/arap_deformation.h"

namespace sa {

struct DeformOptions {
    /// Bounds K on d^c and d^vol: numbers > 1, or kInfinity (no bound).
    double conformal_bound = kInfinity;
    double volumetric_bound = kInfinity;
    /// Find both bounds by the optimal-bound loop (then the two bounds above must be infinite).
    bool optimal_bound = false;
    int optimal_bound_rounds = 10;
    /// The rounds stop when neither largest distortion K drops by more than this share of K - 1.
    double optimal_bound_tolerance = 5e-4;
    /// Rounds after the first solve regions around every simplex within this share of a bound
    /// (OptimalBoundOptions::submesh_band), the rest of the pose fixed.
    double optimal_bound_band = 0.5;
    /// Weight of E_m (the paper's mu = 1000).
    double mu = 1000.0;
    /// How the disassembly projects the start's A_i^0. Rotations are inside every pair of bounds
    /// (d^c = d^vol = 1); a bounded-distortion projection (bounded:K) keeps more of the start
    /// but must land inside both bounds.
    Initialization initialization = Initialization::kClosestRotation;
    /// The ARAP start (geometry/maps/arap_deformation.h).
    ArapOptions start;
    /// Wall-clock limit on the whole run, in seconds.
    double max_time_seconds = kInfinity;
    int num_threads = 0;  ///< 0 = all cores

    /// Throws InvalidArgumentError naming the first bad field and its value.
    void validate() const;
};

}  // namespace sa
