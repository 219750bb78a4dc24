#pragma once
// The largest step that keeps a linear part positively oriented: the smallest t > 0 with
// det(A + t B) = 0, a quadratic in 2D and a cubic in 3D. Every barrier on a distortion is +inf
// from det A <= 0 on, so this is the max_step of each of them (the bound itself is left to the
// line search's rejection of +inf unless an energy knows a closed form, as SimplexEnergy does).

#include <Eigen/Geometry>
#include <array>

#include "energies/polynomial_roots.h"
#include "optim/types.h"

namespace sa {

/// Coefficients of det(A + t B) = c0 + c1 t + c2 t^2 (+ c3 t^3).
template <int D>
std::array<double, 4> determinant_polynomial(const Mat<D>& A, const Mat<D>& B) {
    if constexpr (D == 2) {
        const double c0 = A.determinant(), c2 = B.determinant();
        return {c0, (A + B).determinant() - c0 - c2, c2, 0.0};
    } else {
        // det(A + tB) = det A + t <cof A, B> + t^2 <A, cof B> + t^3 det B.
        auto cofactor = [](const Mat<3>& M) {
            Mat<3> C;
            C.col(0) = M.col(1).cross(M.col(2));
            C.col(1) = M.col(2).cross(M.col(0));
            C.col(2) = M.col(0).cross(M.col(1));
            return C;
        };
        return {A.determinant(), cofactor(A).cwiseProduct(B).sum(),
                A.cwiseProduct(cofactor(B)).sum(), B.determinant()};
    }
}

/// The smallest t > 0 with det(A + t B) = 0, or +inf.
template <int D>
double orientation_step(const Mat<D>& A, const Mat<D>& B) {
    const std::array<double, 4> det = determinant_polynomial<D>(A, B);
    return smallest_positive_root(det[0], det[1], det[2], det[3]);
}

}  // namespace sa
