#pragma once
// The closest rotation to a D x D matrix M (D = 2, 3) in the Frobenius norm: the R in SO(D)
// (det R = +1) that maximizes tr(R^T M). With M = U S V^T that is U diag(1, ..., 1, det(U V^T))
// V^T: for det M < 0 the smallest singular direction is flipped, the closest rotation and not
// the closest orthogonal matrix (as closest_rotation() of frontends/simplex_assembly/disassembly.h,
// which takes an SVD). It is the rotation of the ARAP local step (geometry/maps/arap_local_step.h),
// called once per simplex per iteration, so it avoids the SVD:
//
//   D = 2  closed form: (cos, sin) along (M_00 + M_11, M_10 - M_01).
//   D = 3  Horn's quaternion form (Horn 1987, "Closed-form solution of absolute orientation
//          using unit quaternions"): tr(R(q)^T M) = q^T N(M) q for a unit quaternion q and a
//          symmetric, traceless 4 x 4 N(M), so R's quaternion is N's eigenvector of the largest
//          eigenvalue. It is found by Newton iterations on the Rayleigh quotient q^T N q over unit
//          quaternions, from the quaternion of `hint` (the previous iterate's rotation: an ARAP
//          iteration moves it little, and one or two iterations suffice). Each iteration works
//          in the frame of the current rotation R: with M' = R^T M, the step is the rotation of
//          quaternion (1, v) / |(1, v)| with (2 tr(M') I - M' - M'^T) v = vee(M' - M'^T), whose
//          matrix is minus the Rayleigh quotient's Hessian. A positive definite Hessian at the
//          last iterate certifies the largest eigenvalue, not another stationary point; when it
//          is not clearly so (a poor hint; or M near a matrix with several closest rotations,
//          as the rank-one or the reflected ones with two equal singular values, where that
//          Hessian is near singular) cyclic Jacobi iterations on N in the current frame decide.
//          Either way the result is exact to round-off: its trace tr(R^T M) is within a few
//          units of round-off of the SVD's, and R is orthonormal with det R = 1 to round-off.
//
// A degenerate M (several maximizers, e.g. M = 0) gives one of them, the hint's rotation when
// it is one; a non-finite M gives the identity.

#include "optim/types.h"

namespace sa {

/// The closest rotation to M (D x D, D = 2 or 3), from a cold start.
template <int D>
Mat<D> fit_rotation(const Mat<D>& M);

/// The same, started from `hint`: any matrix, best a rotation or a positive multiple of one near
/// the answer (the previous iterate's; a zero or non-finite hint is a cold start). The hint only
/// changes the speed, and which maximizer a degenerate M gets.
template <int D>
Mat<D> fit_rotation(const Mat<D>& M, const Mat<D>& hint);

}  // namespace sa
