#pragma once
// One solve of H z = b for a sparse Hermitian positive definite H, given its lower triangle:
// CHOLMOD's supernodal LL^H of the complex matrix, ordered by AMD, factored once.
//
// A real symmetric system [L -C; C L] [u; v] = [r; s] with C antisymmetric (C^T = -C) is the
// complex system (L + iC)(u + iv) = r + is: the complex one has half the unknowns and L's pattern,
// so its ordering costs half as much and its factor stores fewer numbers than the real one's,
// whose u and v blocks fill each other in wherever C couples them. The least-squares conformal
// map is such a system (geometry/maps/initial_maps.cpp; figures: docs/measurements.md, "Planar
// parameterization at scale").
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <complex>
#include <optional>

namespace sa {

/// Solves H z = rhs, H Hermitian positive definite given by its lower triangle (square,
/// column-major; the diagonal real). Returns nothing when H is not positive definite.
std::optional<Eigen::VectorXcd> solve_hermitian_positive_definite(
    const Eigen::SparseMatrix<std::complex<double>>& lower, const Eigen::VectorXcd& rhs);

}  // namespace sa
