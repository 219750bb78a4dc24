#include "optim/hermitian_solve.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "optim/errors.h"

namespace sa {
namespace {

using Complex = std::complex<double>;

/// A path graph's Laplacian plus `shift` on the diagonal (n x n, real), and an antisymmetric
/// coupling C on the same edges, scaled by `coupling`. L + iC is positive definite when the
/// shift makes it diagonally dominant, and indefinite without a shift (each edge's 2 x 2 block
/// w [1, -1 - ic; -1 + ic, 1] has the eigenvalue w (1 - sqrt(1 + c^2)) < 0).
struct Fixture {
    Eigen::MatrixXd laplacian, antisymmetric;
};

Fixture path_system(int n, double shift, double coupling) {
    Fixture f{Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, n)};
    for (int k = 0; k + 1 < n; ++k) {
        const double w = 1.0 + 0.1 * k;
        f.laplacian(k, k) += w;
        f.laplacian(k + 1, k + 1) += w;
        f.laplacian(k, k + 1) = f.laplacian(k + 1, k) = -w;
        f.antisymmetric(k + 1, k) = coupling * w * (k % 2 == 0 ? 1.0 : -0.5);
        f.antisymmetric(k, k + 1) = -f.antisymmetric(k + 1, k);
    }
    f.laplacian.diagonal().array() += shift;
    return f;
}

Eigen::SparseMatrix<Complex> lower_of(const Eigen::MatrixXcd& h) {
    std::vector<Eigen::Triplet<Complex>> entries;
    for (int c = 0; c < h.cols(); ++c) {
        for (int r = c; r < h.rows(); ++r) {
            if (h(r, c) != Complex(0.0)) entries.emplace_back(r, c, h(r, c));
        }
    }
    Eigen::SparseMatrix<Complex> lower(h.rows(), h.cols());
    lower.setFromTriplets(entries.begin(), entries.end());
    return lower;
}

TEST(HermitianSolve, SolvesTheRealSystemItStandsFor) {
    // [L -C; C L] [u; v] = [r; s] and (L + iC)(u + iv) = r + is have the same solution.
    const int n = 40;
    const Fixture f = path_system(n, 3.0, 0.8);
    Eigen::MatrixXd real_form(2 * n, 2 * n);
    real_form << f.laplacian, -f.antisymmetric, f.antisymmetric, f.laplacian;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::VectorXd b(2 * n);
    for (int k = 0; k < 2 * n; ++k) b[k] = uniform(random);
    const Eigen::VectorXd expected = real_form.ldlt().solve(b);

    const Eigen::MatrixXcd h =
        f.laplacian.cast<Complex>() + Complex(0.0, 1.0) * f.antisymmetric.cast<Complex>();
    Eigen::VectorXcd rhs(n);
    for (int k = 0; k < n; ++k) rhs[k] = Complex(b[k], b[n + k]);
    const auto z = solve_hermitian_positive_definite(lower_of(h), rhs);
    ASSERT_TRUE(z.has_value());
    for (int k = 0; k < n; ++k) {
        EXPECT_NEAR((*z)[k].real(), expected[k], 1e-10);
        EXPECT_NEAR((*z)[k].imag(), expected[n + k], 1e-10);
    }
}

TEST(HermitianSolve, ReportsAMatrixThatIsNotPositiveDefinite) {
    const Fixture f = path_system(12, 0.0, 3.0);
    const Eigen::MatrixXcd h =
        f.laplacian.cast<Complex>() + Complex(0.0, 1.0) * f.antisymmetric.cast<Complex>();
    EXPECT_FALSE(
        solve_hermitian_positive_definite(lower_of(h), Eigen::VectorXcd::Ones(12)).has_value());
}

TEST(HermitianSolve, RejectsMismatchedSizes) {
    const Fixture f = path_system(5, 1.0, 0.1);
    EXPECT_THROW(solve_hermitian_positive_definite(lower_of(f.laplacian.cast<Complex>()),
                                                   Eigen::VectorXcd::Ones(4)),
                 InvalidArgumentError);
}

}  // namespace
}  // namespace sa
