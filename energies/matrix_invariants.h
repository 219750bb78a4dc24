#pragma once
// Invariants of a D x D matrix A (D = 2, 3) from which every distortion of section 3 is built,
// either as plain values or with exact first and second derivatives with respect to vec(A).
//
// vec(A) is column-major (Eigen's order): in 2D (A00, A10, A01, A11); in 3D the three columns
// one after the other. With sigma_k the singular values of A:
//   I1 = |A|_F^2            = sum_k sigma_k^2
//   I2 = sum_{k<l} sigma_k^2 sigma_l^2   (= J^2 in 2D, = |cof A|_F^2 in 3D)
//   J  = det A              = prod_k sigma_k (signed)
//   S  = sum_k sigma_k      (the trace norm; computed only when asked: an SVD in 3D)
// so that |A^-1|_F^2 = (D == 2 ? I1 : I2) / J^2. Derivatives are closed-form: no automatic
// differentiation inside, and no SVD unless S is requested. S is valid for det A > 0.

#include <Eigen/LU>

#include "optim/dual.h"
#include "optim/types.h"

namespace sa {

template <class S>
struct MatrixInvariants {
    S I1;
    S I2;
    S J;
    S sigma_sum;  ///< zero unless requested
};

/// Invariants of A as plain numbers.
template <int D>
MatrixInvariants<double> matrix_invariants(const Mat<D>& A, bool with_sigma_sum);

/// Invariants of A with gradients and Hessians with respect to vec(A).
template <int D>
MatrixInvariants<Dual<D * D>> matrix_invariants_with_derivatives(const Mat<D>& A,
                                                                 bool with_sigma_sum);

/// A as a D x D matrix from its column-major vector.
template <int D>
Mat<D> unvec(const Vec<D * D>& a) {
    return Eigen::Map<const Mat<D>>(a.data());
}

}  // namespace sa
