#include "energies/rotation_invariant_projection.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <cmath>

namespace sa {

template <int D>
bool project_rotation_invariant_hessian(const Mat<D>& A, Mat<D * D>& h, ProjectionMode mode,
                                        double epsilon) {
    constexpr int N = D * D;
    if (mode == ProjectionMode::kNone) return false;
    if (is_diagonally_dominant_above(h, epsilon)) return false;
    if (!h.allFinite()) return false;
    if (!(A.determinant() > 0.0)) return project_hessian_block<N>(h, mode, epsilon);

    const Eigen::JacobiSVD<Mat<D>> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Mat<D>& U = svd.matrixU();
    const Mat<D>& V = svd.matrixV();
    // Column i + D j is vec(u_i v_j^T): rows D c .. D c + D - 1 hold u_i * V(c, j).
    Mat<N> basis;
    for (int j = 0; j < D; ++j) {
        for (int i = 0; i < D; ++i) {
            for (int c = 0; c < D; ++c) {
                basis.col(i + D * j).template segment<D>(D * c) = U.col(i) * V(c, j);
            }
        }
    }
    // Only the entries of the rotated Hessian B^T h B that the structure allows are read: the
    // D x D block of the diagonal directions and the 2 x 2 block of each off-diagonal pair.
    const Mat<N> h_basis = h.lazyProduct(basis);  // Eigen's general product is slower here
    auto rotated = [&](int r, int c) { return basis.col(r).dot(h_basis.col(c)); };

    // The D x D block of the diagonal directions E_ii.
    Mat<D> diagonal_block;
    for (int i = 0; i < D; ++i) {
        for (int k = 0; k <= i; ++k)
            diagonal_block(i, k) = diagonal_block(k, i) = rotated(i + D * i, k + D * k);
    }
    const Eigen::SelfAdjointEigenSolver<Mat<D>> eig(diagonal_block);
    // The flip (a + b) and twist (a - b) eigenvalues of each off-diagonal pair i < j.
    constexpr int kPairs = D * (D - 1) / 2;
    std::array<double, kPairs> flip, twist;
    std::array<int, kPairs> first, second;  // rotated indices of E_ij and E_ji
    for (int i = 0, k = 0; i < D; ++i) {
        for (int j = i + 1; j < D; ++j, ++k) {
            const int p = i + D * j, q = j + D * i;
            const double a = 0.5 * (rotated(p, p) + rotated(q, q));
            const double b = 0.5 * (rotated(p, q) + rotated(q, p));
            flip[k] = a + b;
            twist[k] = a - b;
            first[k] = p;
            second[k] = q;
        }
    }

    if (mode == ProjectionMode::kShift) {
        double smallest = eig.eigenvalues()(0);
        for (int k = 0; k < kPairs; ++k) smallest = std::min({smallest, flip[k], twist[k]});
        if (smallest >= epsilon) return false;
        h.diagonal().array() += epsilon - smallest;
        return true;
    }

    bool changed = false;
    auto adjust = [&](double value) {
        const double v = std::max(mode == ProjectionMode::kAbs ? std::abs(value) : value, epsilon);
        changed |= v != value;
        return v;
    };
    Vec<D> values = eig.eigenvalues();
    for (int i = 0; i < D; ++i) values(i) = adjust(values(i));
    for (int k = 0; k < kPairs; ++k) {
        flip[k] = adjust(flip[k]);
        twist[k] = adjust(twist[k]);
    }
    if (!changed) return false;

    // h = B P B^T with P the projected blocks: first B P column by column (each column of P has
    // at most D nonzeros), then one dense product.
    const Mat<D> block = eig.eigenvectors() * values.asDiagonal() * eig.eigenvectors().transpose();
    Mat<N> basis_projected;
    for (int k = 0; k < D; ++k) {
        auto column = basis_projected.col(k + D * k);
        column = basis.col(0) * block(0, k);
        for (int i = 1; i < D; ++i) column += basis.col(i + D * i) * block(i, k);
    }
    for (int k = 0; k < kPairs; ++k) {
        const int p = first[k], q = second[k];
        const double same = 0.5 * (flip[k] + twist[k]), cross = 0.5 * (flip[k] - twist[k]);
        basis_projected.col(p) = basis.col(p) * same + basis.col(q) * cross;
        basis_projected.col(q) = basis.col(q) * same + basis.col(p) * cross;
    }
    h = basis_projected.lazyProduct(basis.transpose());
    return true;
}

template bool project_rotation_invariant_hessian<2>(const Mat<2>&, Mat<4>&, ProjectionMode, double);
template bool project_rotation_invariant_hessian<3>(const Mat<3>&, Mat<9>&, ProjectionMode, double);

}  // namespace sa
