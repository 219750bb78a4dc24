#pragma once
// Positive-definite projection of the Hessian of a rotation-invariant energy of a D x D matrix,
// from the singular vectors of the matrix instead of an eigen-decomposition of the whole
// D^2 x D^2 Hessian (the structure used by Smith, De Goes and Kim 2019, "Analytic eigensystems
// for isotropic distortion energies", here read off the given Hessian rather than derived per
// energy).
//
// Valid for the Hessian h (with respect to vec(A), column-major) of
//     f(A) + c |A - A0|_F^2
// where f depends on A only through its singular values and the sign of det A, i.e.
// f(P A Q) = f(A) for orthogonal P, Q with det P det Q = 1, and at a point with det A > 0. Every
// distortion of distortion.h and the barriers of barrier.h on them are such f; kDifference adds
// the c |A - A0|^2 part, whose Hessian 2c I looks the same in every orthonormal basis.
//
// Why: let A = U S V^T be an SVD (det U det V = 1 because det A > 0) and E_ij = u_i v_j^T. In the
// orthonormal basis {vec(E_ij)} the Hessian is that of f at the diagonal S, and f(S + X) =
// f(S + R X R) for every diagonal sign matrix R. So the Hessian couples the diagonal entries X_ii
// only among themselves (a D x D block) and each off-diagonal pair (X_ij, X_ji) only within
// itself, where it is [[a, b], [b, a]] (the perturbed matrix's invariants are symmetric in X_ij
// and X_ji). Its eigenvectors are (E_ij + E_ji)/sqrt 2 and (E_ij - E_ji)/sqrt 2 (flip and twist)
// with eigenvalues a + b and a - b; the rest come from the D x D block.
//
// Cost per block: one D x D SVD, the product h B and from it only the entries of B^T h B that the
// structure leaves (the D x D block and the 2 x 2 pair blocks), a D x D eigenproblem and, when
// the block changes, B P B^T with P that sparse; against the eigen-decomposition of a 4 x 4 (2D)
// or 9 x 9 (3D) matrix.

#include "optim/hessian_projection.h"
#include "optim/types.h"

namespace sa {

/// Projects `h`, the Hessian at `A` of an energy as above, in place with `mode` and `epsilon`
/// exactly as project_hessian_block() does (same eigenvalues, same result up to rounding).
/// Returns true when `h` was changed. Falls back to project_hessian_block() when det A <= 0.
template <int D>
bool project_rotation_invariant_hessian(const Mat<D>& A, Mat<D * D>& h, ProjectionMode mode,
                                        double epsilon);

extern template bool project_rotation_invariant_hessian<2>(const Mat<2>&, Mat<4>&, ProjectionMode,
                                                           double);
extern template bool project_rotation_invariant_hessian<3>(const Mat<3>&, Mat<9>&, ProjectionMode,
                                                           double);

}  // namespace sa
