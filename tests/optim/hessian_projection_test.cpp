#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <random>

#include "optim/hessian_projection.h"

namespace sa {
namespace {

// Q diag(eigenvalues) Q^T with a random orthogonal Q, computed at dynamic size: a fixed-size
// product of 20 x 20 matrices is slow to compile.
template <int N>
Mat<N> random_symmetric(std::mt19937& rng, const Vec<N>& eigenvalues) {
    std::normal_distribution<double> normal;
    Eigen::MatrixXd a(N, N);
    for (int i = 0; i < N * N; ++i) a(i) = normal(rng);
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(a);
    const Eigen::MatrixXd q = qr.householderQ();
    const Eigen::VectorXd d = eigenvalues;
    return Eigen::MatrixXd(q * d.asDiagonal() * q.transpose());
}

// The eigenvalues of a symmetric block in increasing order, by one dynamic-size solver for every
// size: fixed-size solvers are slow to compile, and the library's own are the ones under test.
Eigen::VectorXd eigenvalues(const Eigen::MatrixXd& h) {
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(h, Eigen::EigenvaluesOnly).eigenvalues();
}

TEST(HessianProjection, ClampRaisesEveryEigenvalueToEpsilon) {
    std::mt19937 rng(1);
    const double eps = 1e-3;
    Mat<4> h = random_symmetric(rng, Vec<4>(-5.0, -0.1, 2.0, 7.0));
    EXPECT_TRUE(project_hessian_block<4>(h, ProjectionMode::kClamp, eps));
    const Eigen::VectorXd values = eigenvalues(h);
    EXPECT_NEAR(values(0), eps, 1e-12);
    EXPECT_NEAR(values(1), eps, 1e-12);
    EXPECT_NEAR(values(2), 2.0, 1e-12);
    EXPECT_NEAR(values(3), 7.0, 1e-12);
}

TEST(HessianProjection, AbsMirrorsNegativeEigenvalues) {
    std::mt19937 rng(2);
    Mat<4> h = random_symmetric(rng, Vec<4>(-5.0, -0.1, 2.0, 7.0));
    EXPECT_TRUE(project_hessian_block<4>(h, ProjectionMode::kAbs, 1e-8));
    const Eigen::VectorXd values = eigenvalues(h);
    EXPECT_NEAR(values(0), 0.1, 1e-12);
    EXPECT_NEAR(values(1), 2.0, 1e-12);
    EXPECT_NEAR(values(2), 5.0, 1e-12);
    EXPECT_NEAR(values(3), 7.0, 1e-12);
}

TEST(HessianProjection, ShiftAddsAMultipleOfTheIdentity) {
    std::mt19937 rng(3);
    const Mat<4> original = random_symmetric(rng, Vec<4>(-5.0, -0.1, 2.0, 7.0));
    Mat<4> h = original;
    EXPECT_TRUE(project_hessian_block<4>(h, ProjectionMode::kShift, 1e-8));
    EXPECT_NEAR(eigenvalues(h)(0), 1e-8, 1e-11);
    const Mat<4> difference = h - original;
    EXPECT_TRUE(difference.isApprox((5.0 + 1e-8) * Mat<4>::Identity(), 1e-12));
}

TEST(HessianProjection, PositiveDefiniteBlockIsUnchanged) {
    std::mt19937 rng(4);
    for (ProjectionMode mode :
         {ProjectionMode::kClamp, ProjectionMode::kAbs, ProjectionMode::kShift}) {
        const Mat<4> original = random_symmetric(rng, Vec<4>(0.5, 1.0, 2.0, 3.0));
        Mat<4> h = original;
        project_hessian_block<4>(h, mode, 1e-8);
        EXPECT_TRUE(h.isApprox(original, 1e-13)) << to_string(mode);
    }
}

TEST(HessianProjection, DiagonallyDominantBlockIsSkippedExactly) {
    Mat<4> h;
    h << 4, 1, -1, 0.5, 1, 5, 2, 1, -1, 2, 6, -2, 0.5, 1, -2, 7;
    const Mat<4> original = h;
    EXPECT_TRUE(is_diagonally_dominant_above(h, 1e-8));
    EXPECT_FALSE(project_hessian_block<4>(h, ProjectionMode::kClamp, 1e-8));
    EXPECT_EQ(h, original);
}

TEST(HessianProjection, NoneLeavesIndefiniteBlock) {
    std::mt19937 rng(5);
    const Mat<4> original = random_symmetric(rng, Vec<4>(-1.0, 1.0, 2.0, 3.0));
    Mat<4> h = original;
    EXPECT_FALSE(project_hessian_block<4>(h, ProjectionMode::kNone, 1e-8));
    EXPECT_EQ(h, original);
}

// Past kLargestFixedSizeProjection, blocks go to a solver on stack storage, and past
// kLargestStackProjection to a dynamic-size one: same modes, same results.
template <int N>
void expect_projected_alike(unsigned seed) {
    std::mt19937 rng(seed);
    const Vec<N> spectrum = Vec<N>::LinSpaced(-5.0, 7.0);
    const double eps = 1e-3;

    Mat<N> h = random_symmetric<N>(rng, spectrum);
    EXPECT_TRUE(project_hessian_block<N>(h, ProjectionMode::kClamp, eps));
    EXPECT_LT((eigenvalues(h) - spectrum.cwiseMax(eps)).cwiseAbs().maxCoeff(), 1e-11);

    h = random_symmetric<N>(rng, spectrum);
    EXPECT_TRUE(project_hessian_block<N>(h, ProjectionMode::kAbs, eps));
    Vec<N> mirrored = spectrum.cwiseAbs().cwiseMax(eps);
    std::sort(mirrored.begin(), mirrored.end());
    EXPECT_LT((eigenvalues(h) - mirrored).cwiseAbs().maxCoeff(), 1e-11);

    const Mat<N> original = random_symmetric<N>(rng, spectrum);
    h = original;
    EXPECT_TRUE(project_hessian_block<N>(h, ProjectionMode::kShift, eps));
    EXPECT_TRUE((h - original).isApprox((5.0 + eps) * Mat<N>::Identity(), 1e-11));

    const Mat<N> positive = random_symmetric<N>(rng, Vec<N>::LinSpaced(0.5, 3.0));
    h = positive;
    EXPECT_FALSE(project_hessian_block<N>(h, ProjectionMode::kClamp, eps));
    EXPECT_EQ(h, positive);
}

TEST(HessianProjection, LargeBlocksAreProjectedAlike) {
    static_assert(9 > kLargestFixedSizeProjection && 9 <= kLargestStackProjection);
    expect_projected_alike<9>(6);
    static_assert(20 > kLargestStackProjection);
    expect_projected_alike<20>(7);
}

}  // namespace
}  // namespace sa
