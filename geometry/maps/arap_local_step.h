#pragma once
// The local step of as-rigid-as-possible (ARAP) and as-similar-as-possible (ASAP) iterations on
// the least squares of Eq. 6 (geometry/maps/vertex_recovery.h, the global step):
//     Q(x, M) = sum_i sum_{edges (a, b) of s_i} |M_i (u_a - u_b) - (x_a - x_b)|^2,
// u the rest corners in s_i's frame. For fixed positions x with linear parts A_i,
// x_a - x_b = A_i (u_a - u_b), so s_i's terms are tr((M_i - A_i) C_i (M_i - A_i)^T) with the edge
// covariance C_i = sum_edges (u_a - u_b)(u_a - u_b)^T = (D + 1) U U^T (U: corners, centred).
// Minimizing over rotations gives R_i = closest_rotation(A_i C_i) (tr(R C R^T) is constant);
// over similarities s R, the same R and s = tr(R^T A_i C_i) / tr(C_i). Alternating this step
// with the global step never increases Q: the plain iteration is monotone.
// (Projecting A_i itself, as the disassembly does, is the same step when C_i is a multiple of
// the identity, i.e. for regular simplices.)

#include <vector>

#include "geometry/mesh/rest_frames.h"

namespace sa {

/// Fills M (resized to A's size) with each simplex's best rotation, or similarity when
/// `similarity`, for the linear parts A; returns Q(x, M). A non-finite A_i gets the identity.
/// The rotations are geometry/maps/rotation_fit.h's, started from M's entries when M already has
/// A's size (the last iteration's fit: the same result to round-off, in fewer operations). Parallel
/// over simplices; the result does not depend on the thread count.
template <int D>
double fit_rigid_parts(const RestFrames<D>& frames, const std::vector<Mat<D>>& A, bool similarity,
                       std::vector<Mat<D>>& M);

}  // namespace sa
