#pragma once
// Per-element projection of a symmetric Hessian block onto the positive-definite matrices, so that
// the assembled Hessian is positive semi-definite and Newton steps descend.
//
// Modes (eigenvalues k_i of the block H):
//   kClamp    k_i := max(k_i, epsilon)                      (TinyAD's default)
//   kAbs      k_i := max(|k_i|, epsilon)                    (mirror negative curvature)
//   kShift    H := H + (epsilon - min k_i) I if min k_i < epsilon
//             (the paper's Hessian modification, step 1 of section 4.4, with epsilon = 1e-8)
//   kNone     H unchanged
// A block is left unchanged, without an eigen-decomposition, when Gershgorin's theorem already
// proves every eigenvalue >= epsilon: H_ii - sum_{j != i} |H_ij| >= epsilon for every row i.

#include <Eigen/Core>
#include <cmath>
#include <string>

#include "optim/types.h"

namespace sa {

enum class ProjectionMode { kClamp, kAbs, kShift, kNone };

std::string to_string(ProjectionMode mode);
/// "clamp", "abs", "shift" or "none"; throws InvalidArgumentError otherwise.
ProjectionMode parse_projection(const std::string& name);

/// True when every Gershgorin disc of `h` lies in [epsilon, inf).
template <class Matrix>
bool is_diagonally_dominant_above(const Matrix& h, double epsilon) {
    for (Eigen::Index i = 0; i < h.rows(); ++i) {
        double off = 0.0;
        for (Eigen::Index j = 0; j < h.cols(); ++j) {
            if (j != i) off += std::abs(h(i, j));
        }
        if (h(i, i) - off < epsilon) return false;
    }
    return true;
}

/// The eigen-solvers are compiled once, in hessian_projection.cpp: one of fixed size for each
/// block of up to kLargestFixedSizeProjection variables (the 2D linear parts' blocks and
/// smaller), one for any size up to kLargestStackProjection on storage of that capacity (the 3D
/// blocks of 9 and 12 variables, as fast there as fixed-size ones and without a heap
/// allocation), and one for larger blocks. A fixed-size solver per size, instantiated in every
/// unit that projects such blocks, is slow to compile (docs/measurements.md, "Build time").
inline constexpr int kLargestFixedSizeProjection = 4;
inline constexpr int kLargestStackProjection = 16;

/// Projects the symmetric block `h` in place (see the modes above), of any size. Returns true
/// when `h` was changed. A block with a non-finite entry is left as it is and reported as
/// unchanged; the caller checks finiteness.
bool project_hessian_block(MatrixRef h, ProjectionMode mode, double epsilon);

namespace detail {

/// The eigen-decomposition part of project_hessian_block<N>(), instantiated in
/// hessian_projection.cpp for N = 1 .. kLargestFixedSizeProjection.
template <int N>
bool project_by_eigenvalues(Mat<N>& h, ProjectionMode mode, double epsilon);
/// The same for a block of n <= kLargestStackProjection variables at h (column-major), checked
/// already (finite, not diagonally dominant).
bool project_small_block_by_eigenvalues(double* h, int n, ProjectionMode mode, double epsilon);

}  // namespace detail

/// project_hessian_block() on a fixed-size block.
template <int N>
bool project_hessian_block(Mat<N>& h, ProjectionMode mode, double epsilon) {
    if (mode == ProjectionMode::kNone) return false;
    if (is_diagonally_dominant_above(h, epsilon)) return false;
    if (!h.allFinite()) return false;
    if constexpr (N <= kLargestFixedSizeProjection) {
        return detail::project_by_eigenvalues<N>(h, mode, epsilon);
    } else if constexpr (N <= kLargestStackProjection) {
        return detail::project_small_block_by_eigenvalues(h.data(), N, mode, epsilon);
    } else {
        return project_hessian_block(MatrixRef(h), mode, epsilon);
    }
}

}  // namespace sa
