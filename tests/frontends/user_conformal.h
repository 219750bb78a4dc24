#pragma once
// The conformal distortion written as a user would, once over the scalar type: the tests compare
// a barrier on it with the built-in one (energies/distortion.h; 2D ‖A‖²/(2 det A), 3D
// (‖A‖²‖A⁻¹‖² − 1)/8, both 1 at a similarity).

#include <Eigen/Core>

namespace sa {

template <int D>
struct UserConformal {
    static constexpr bool rotation_invariant = true;
    template <class T>
    T operator()(const Eigen::Matrix<T, D, D>& A) const {
        if constexpr (D == 2) {
            return A.squaredNorm() / (2.0 * A.determinant());
        } else {
            return (A.squaredNorm() * A.inverse().squaredNorm() - 1.0) / 8.0;
        }
    }
};

}  // namespace sa
