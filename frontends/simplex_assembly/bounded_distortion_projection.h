#pragma once
// Projection onto the bounded-distortion set (Kovalsky et al., "Large-scale bounded distortion
// mappings", 2015; the paper's section 4.2 and Figure 6(c)):
//     D_K = { A : det A > 0, sigma_max(A) / sigma_min(A) <= K },   K >= 1.
// With A = U diag(sigma) V^T, the closest matrix of D_K in the Frobenius norm is
// U diag(sigma') V^T where sigma' is the closest point of the cone
// { s : t <= s_i <= K t for some t > 0 } to sigma: for a fixed t that is the clamp
// s_i = clamp(sigma_i, t, K t), and t minimizes the convex, piecewise quadratic
//     f(t) = sum_{sigma_i < t} (t - sigma_i)^2 + sum_{sigma_i > K t} (sigma_i - K t)^2,
// solved exactly on each interval between the breakpoints sigma_i and sigma_i / K.
// K = 1 gives the closest similarity (t = the mean singular value), K = inf leaves sigma as is.
//
// An inverted A (det A < 0) is first reflected along its smallest singular direction, as the
// other projections of the disassembly do (frontends/simplex_assembly/disassembly.h): U's last
// column is negated, so that U diag(sigma') V^T has det > 0.

#include "optim/types.h"

namespace sa {

/// The clamped singular values sigma' for `sigma` (any order, each >= 0) and the bound K >= 1
/// (kInfinity allowed). Returns `sigma` itself when it is already inside the cone; all zeros
/// stay zero.
template <int D>
Vec<D> clamp_singular_values(const Vec<D>& sigma, double K);

/// The projection of A onto D_K (see above). A that is already inside D_K is returned unchanged
/// (bit for bit). The zero matrix maps to itself (no direction to keep; the disassembly replaces
/// it by the median scale). Throws InvalidArgumentError unless K >= 1 (kInfinity allowed) and A
/// is finite.
template <int D>
Mat<D> project_bounded_distortion(const Mat<D>& A, double K);

/// The largest conformal distortion d^c of section 3 on D_K in dimension `d` (2 or 3), reached
/// at diag(K, 1[, 1]): (K + 1/K) / 2 in 2D, ((K + 1/K) / 2)^2 in 3D. A barrier on d^c with bound
/// K^conf accepts every projection onto D_K when this is below K^conf (the paper's
/// K^conf = (delta + 1/delta) / 2 in 2D). kInfinity for K = kInfinity.
double largest_conformal_distortion(double K, int d);

}  // namespace sa
