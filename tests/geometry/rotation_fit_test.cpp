#include "geometry/maps/rotation_fit.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>
#include <random>

#include "tests/fixtures/random_matrices.h"

namespace sa {
namespace {

/// The SVD's closest rotation (as frontends/simplex_assembly/disassembly.h's) and how well
/// determined it is: the sum of the two smallest singular values, the smaller one signed by det M
/// (the closest rotation is unique when it is > 0, and moves by about round-off / gap under
/// round-off).
template <int D>
struct SvdFit {
    Mat<D> rotation;
    double gap = 0.0;
};

template <int D>
SvdFit<D> svd_fit(const Mat<D>& M) {
    const Eigen::JacobiSVD<Mat<D>> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Mat<D> U = svd.matrixU();
    const Mat<D>& V = svd.matrixV();
    const double sign = (U * V.transpose()).determinant() < 0.0 ? -1.0 : 1.0;
    U.col(D - 1) *= sign;
    const auto& s = svd.singularValues();
    return {U * V.transpose(), s[D - 2] + sign * s[D - 1]};
}

template <int D>
Mat<D> random_rotation(std::mt19937_64& rng) {
    return svd_fit<D>(gaussian_matrix<D>(rng)).rotation;
}

/// R is a rotation to round-off, no farther from M than the SVD's rotation (tr(R^T M), the
/// only term of |R - M|^2 that depends on R, within round-off of the SVD's), and the SVD's
/// rotation itself where that is well determined.
template <int D>
void expect_closest(const Mat<D>& M, const Mat<D>& R, const char* what) {
    SCOPED_TRACE(what);
    const SvdFit<D> svd = svd_fit<D>(M);
    const double scale = M.norm();
    EXPECT_LT((R.transpose() * R - Mat<D>::Identity()).norm(), 1e-14);
    EXPECT_NEAR(R.determinant(), 1.0, 1e-14);
    EXPECT_GE((R.transpose() * M).trace(), (svd.rotation.transpose() * M).trace() - 1e-14 * scale);
    if (svd.gap > 1e-6 * scale) {
        EXPECT_LT((R - svd.rotation).norm(), 1e-14 * scale / svd.gap) << M;
    }
}

template <int D>
void expect_closest_from_any_start(const Mat<D>& M, const char* what, std::mt19937_64& rng) {
    expect_closest<D>(M, fit_rotation<D>(M), what);
    const Mat<D> exact = svd_fit<D>(M).rotation;
    expect_closest<D>(M, fit_rotation<D>(M, exact), what);
    expect_closest<D>(M, fit_rotation<D>(M, random_rotation<D>(rng)), what);
    expect_closest<D>(M, fit_rotation<D>(M, 3.0 * random_rotation<D>(rng)), what);
    expect_closest<D>(M, fit_rotation<D>(M, gaussian_matrix<D>(rng)), what);
    expect_closest<D>(M, fit_rotation<D>(M, Mat<D>::Zero()), what);
    expect_closest<D>(M, fit_rotation<D>(M, Mat<D>::Constant(std::nan(""))), what);
    if constexpr (D == 3) {  // the worst hint: half a turn away
        const Mat<3> far =
            exact * Eigen::AngleAxisd(M_PI, Eigen::Vector3d(1.0, -2.0, 0.5).normalized())
                        .toRotationMatrix();
        expect_closest<D>(M, fit_rotation<D>(M, far), what);
    }
}

template <int D>
void check_classes() {
    std::mt19937_64 rng(17 + D);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 300; ++trial) {
        // Random matrices, both signs of det.
        expect_closest_from_any_start<D>(gaussian_matrix<D>(rng), "random", rng);
        // Near a rotation, the ARAP case.
        expect_closest_from_any_start<D>(random_rotation<D>(rng) + 1e-3 * gaussian_matrix<D>(rng),
                                         "near a rotation", rng);
        // Near-singular: singular values down to 1e-16, reflected or not.
        Vec<D> s;
        s[0] = 1.0;
        for (int k = 1; k < D; ++k) s[k] = std::pow(10.0, -16.0 * unit(rng));
        Mat<D> M = random_rotation<D>(rng) * s.asDiagonal() * random_rotation<D>(rng);
        expect_closest_from_any_start<D>(M, "near-singular", rng);
        M.col(0) *= -1.0;
        expect_closest_from_any_start<D>(M, "near-singular, reflected", rng);
        // Reflected rotations (an inverted, undistorted simplex) with noise down to 1e-14: the
        // closest rotation is nearly undetermined there.
        M = random_rotation<D>(rng);
        M.row(D - 1) *= -1.0;
        expect_closest_from_any_start<D>(
            M + std::pow(10.0, -14.0 * unit(rng)) * gaussian_matrix<D>(rng), "reflected", rng);
        // Reflected with distinct singular values: well determined again.
        for (int k = 0; k < D; ++k) s[k] = 1.0 + k + unit(rng);
        M = random_rotation<D>(rng) * s.asDiagonal() * random_rotation<D>(rng);
        M.col(D - 1) *= -1.0;
        expect_closest_from_any_start<D>(M, "reflected, distinct singular values", rng);
    }
}

TEST(RotationFit, MatchesTheSvdOnEveryClass2D) {
    check_classes<2>();
}
TEST(RotationFit, MatchesTheSvdOnEveryClass3D) {
    check_classes<3>();
}

// Rotations and their positive multiples over 16 orders of magnitude are their own fit,
// exactly to round-off, from a cold start and from a rotation's hint.
TEST(RotationFit, RotationsAndSimilaritiesAreFixedPoints) {
    std::mt19937_64 rng(5);
    for (int trial = 0; trial < 200; ++trial) {
        const Mat<3> R = random_rotation<3>(rng);
        const Mat<2> R2 = random_rotation<2>(rng);
        const double scale = std::pow(10.0, -8.0 + 16.0 * (trial % 17) / 16.0);
        EXPECT_LT((fit_rotation<3>(scale * R) - R).norm(), 5e-15);
        EXPECT_LT((fit_rotation<3>(scale * R, random_rotation<3>(rng)) - R).norm(), 5e-15);
        EXPECT_LT((fit_rotation<2>(scale * R2) - R2).norm(), 5e-15);
    }
    EXPECT_EQ(fit_rotation<3>(Mat<3>::Identity()), Mat<3>::Identity());
    // Half a turn: N's largest eigenvalue is simple, its quaternion (0, axis).
    const Mat<3> half = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    EXPECT_LT((fit_rotation<3>(half) - half).norm(), 1e-15);
    EXPECT_LT((fit_rotation<3>(half, Mat<3>::Identity()) - half).norm(), 1e-15);
}

// Degenerate matrices: every maximizer is as good; the hint's rotation is kept when it is one.
TEST(RotationFit, DegenerateMatricesKeepTheHint) {
    std::mt19937_64 rng(9);
    const Mat<3> hint = random_rotation<3>(rng);
    EXPECT_LT((fit_rotation<3>(Mat<3>::Zero(), hint) - hint).norm(), 1e-14);
    EXPECT_EQ(fit_rotation<3>(Mat<3>::Zero()), Mat<3>::Identity());
    const Mat<2> hint2 = random_rotation<2>(rng);
    EXPECT_LT((fit_rotation<2>(Mat<2>::Zero(), hint2) - hint2).norm(), 1e-15);
    EXPECT_EQ(fit_rotation<2>(Mat<2>::Zero()), Mat<2>::Identity());
    // diag(1, 1, -1): every rotation about an axis in the xy plane by half a turn, and the
    // identity... all give tr = 1. The hint's rotation is one of them.
    const Mat<3> reflection = Vec<3>(1.0, 1.0, -1.0).asDiagonal();
    EXPECT_NEAR((fit_rotation<3>(reflection).transpose() * reflection).trace(), 1.0, 1e-14);
    EXPECT_TRUE(fit_rotation<3>(reflection, Mat<3>::Identity()).isIdentity(1e-14));
    // Rank one: R must take the right singular vector to the left one; the trace is s_1.
    const Vec<3> u = Vec<3>(1.0, 2.0, 3.0).normalized(), v = Vec<3>(-1.0, 0.5, 2.0).normalized();
    const Mat<3> rank_one = 2.5 * u * v.transpose();
    for (const Mat<3>& R : {fit_rotation<3>(rank_one), fit_rotation<3>(rank_one, hint)}) {
        EXPECT_NEAR((R.transpose() * rank_one).trace(), 2.5, 1e-14);
        EXPECT_LT((R * v - u).norm(), 1e-7);  // sqrt(round-off): the trace is flat to 2nd order
        EXPECT_NEAR(R.determinant(), 1.0, 1e-14);
    }
}

TEST(RotationFit, NonFiniteMatricesGiveTheIdentity) {
    Mat<3> M = Mat<3>::Identity();
    M(1, 2) = std::nan("");
    EXPECT_EQ(fit_rotation<3>(M), Mat<3>::Identity());
    M(1, 2) = kInfinity;
    EXPECT_EQ(fit_rotation<3>(M, Mat<3>::Identity()), Mat<3>::Identity());
    Mat<2> M2 = Mat<2>::Identity();
    M2(0, 1) = -kInfinity;
    EXPECT_EQ(fit_rotation<2>(M2), Mat<2>::Identity());
}

}  // namespace
}  // namespace sa
