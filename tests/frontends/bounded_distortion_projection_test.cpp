#include "frontends/simplex_assembly/bounded_distortion_projection.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <random>

#include "frontends/simplex_assembly/disassembly.h"
#include "optim/errors.h"
#include "tests/fixtures/random_matrices.h"

namespace sa {
namespace {

template <int D>
double ratio(const Mat<D>& A) {
    const Vec<D> s = Eigen::JacobiSVD<Mat<D>>(A).singularValues();
    return s[0] / s[D - 1];
}

// Brute force over t of the clamp cost (the closest point of the cone for a fixed t).
template <int D>
double best_clamp_cost(const Vec<D>& sigma, double K) {
    double best = kInfinity;
    const double hi = sigma.maxCoeff();
    for (int k = 1; k <= 20000; ++k) {
        const double t = hi * k / 20000.0;
        double f = 0.0;
        for (int i = 0; i < D; ++i) {
            const double c = std::clamp(sigma[i], t, K * t);
            f += (c - sigma[i]) * (c - sigma[i]);
        }
        best = std::min(best, f);
    }
    return best;
}

template <int D>
void check_projection(unsigned seed) {
    std::mt19937 rng(seed);
    for (int trial = 0; trial < 200; ++trial) {
        const Mat<D> A = gaussian_matrix<D>(rng);
        for (double K : {1.0, 1.5, 3.0, 10.0}) {
            const Mat<D> P = project_bounded_distortion<D>(A, K);
            // Inside the bounded-distortion set: positive determinant, ratio within K.
            ASSERT_GT(P.determinant(), 0.0);
            EXPECT_LE(ratio<D>(P), K * (1.0 + 1e-10));
            // Idempotent, and the distance is that of the best clamp (the optimal t).
            EXPECT_TRUE(project_bounded_distortion<D>(P, K).isApprox(P, 1e-10));
            if (A.determinant() > 0.0) {
                const Vec<D> sigma = Eigen::JacobiSVD<Mat<D>>(A).singularValues();
                EXPECT_LE((P - A).squaredNorm(), best_clamp_cost<D>(sigma, K) + 1e-9);
                // No matrix of the set near P is closer to A (probe by projected perturbations).
                for (int k = 0; k < 10; ++k) {
                    const Mat<D> other =
                        project_bounded_distortion<D>(P + 0.05 * gaussian_matrix<D>(rng), K);
                    EXPECT_LE((A - P).norm(), (A - other).norm() + 1e-10);
                }
            }
        }
    }
}

TEST(BoundedDistortionProjection, LandsInsideTheBoundAndIsClosest) {
    check_projection<2>(2);
    check_projection<3>(3);
}

TEST(BoundedDistortionProjection, MatricesInsideAreUnchanged) {
    Mat<3> A;
    A << 2.0, 0.3, 0.0, -0.2, 1.5, 0.1, 0.0, 0.4, 1.8;
    ASSERT_GT(A.determinant(), 0.0);
    const double r = ratio<3>(A);
    EXPECT_EQ(project_bounded_distortion<3>(A, r * 1.0001), A);  // bit for bit
    EXPECT_EQ(project_bounded_distortion<3>(A, kInfinity), A);
    EXPECT_NE(project_bounded_distortion<3>(A, r * 0.9), A);
    const Mat<2> R = Eigen::Rotation2Dd(0.7).toRotationMatrix();
    EXPECT_EQ(project_bounded_distortion<2>(R, 1.0), R);
}

TEST(BoundedDistortionProjection, ClampsSingularValuesExactly) {
    // sigma = (4, 1), K = 2: t minimizes (t - 1)^2 + (4 - 2t)^2, t = 9/5: (3.6, 1.8).
    const Vec<2> c = clamp_singular_values<2>(Vec<2>(4.0, 1.0), 2.0);
    EXPECT_NEAR(c[0], 3.6, 1e-14);
    EXPECT_NEAR(c[1], 1.8, 1e-14);
    // sigma = (9, 3, 1), K = 3: the middle one stays; t from (t - 1)^2 + (9 - 3t)^2: t = 2.8.
    const Vec<3> d = clamp_singular_values<3>(Vec<3>(9.0, 3.0, 1.0), 3.0);
    EXPECT_NEAR(d[0], 8.4, 1e-13);
    EXPECT_NEAR(d[1], 3.0, 1e-13);
    EXPECT_NEAR(d[2], 2.8, 1e-13);
    // K = 1: the mean.
    EXPECT_TRUE(clamp_singular_values<3>(Vec<3>(3.0, 2.0, 1.0), 1.0).isApprox(Vec<3>::Constant(2)));
    EXPECT_EQ(clamp_singular_values<2>(Vec<2>::Zero(), 2.0), Vec<2>::Zero());
}

TEST(BoundedDistortionProjection, KOneIsTheClosestSimilarity) {
    std::mt19937 rng(11);
    for (int trial = 0; trial < 20; ++trial) {
        const Mat<3> A = gaussian_matrix<3>(rng);
        EXPECT_TRUE(
            project_bounded_distortion<3>(A, 1.0).isApprox(closest_similarity<3>(A), 1e-10));
    }
}

TEST(BoundedDistortionProjection, InvertedInputsFlipTheirSmallestDirection) {
    Mat<2> A;
    A << 3.0, 0.0, 0.0, -0.5;  // a reflection of the small axis, ratio 6
    // Reflected: diag(3, 0.5), then clamped to ratio 2: t from (t - 0.5)^2 + (3 - 2t)^2 = 1.3.
    const Mat<2> P = project_bounded_distortion<2>(A, 2.0);
    Mat<2> expected;
    expected << 2.6, 0.0, 0.0, 1.3;
    EXPECT_TRUE(P.isApprox(expected, 1e-12));
    // Inside the ratio but inverted: only reflected.
    Mat<3> B = Vec<3>(2.0, 1.5, -1.0).asDiagonal();
    EXPECT_TRUE(project_bounded_distortion<3>(B, 5.0).isApprox(
        Mat<3>(Vec<3>(2.0, 1.5, 1.0).asDiagonal()), 1e-12));
    // Flat: the lost direction gets the clamped scale.
    Mat<3> F = Vec<3>(2.0, 1.0, 0.0).asDiagonal();
    const Mat<3> Q = project_bounded_distortion<3>(F, 4.0);
    EXPECT_GT(Q.determinant(), 0.0);
    EXPECT_LE(ratio<3>(Q), 4.0 * (1.0 + 1e-12));
}

// The paper's conformal distortion, in its closed forms (section 3).
template <int D>
double conformal(const Mat<D>& A) {
    if (D == 2) return A.squaredNorm() / (2.0 * A.determinant());
    return (A.squaredNorm() * A.inverse().squaredNorm() - 1.0) / 8.0;
}

template <int D>
void check_largest_conformal(double K) {
    std::mt19937 rng(17);
    const double largest = largest_conformal_distortion(K, D);
    for (int trial = 0; trial < 2000; ++trial) {
        const Mat<D> P = project_bounded_distortion<D>(4.0 * gaussian_matrix<D>(rng), K);
        EXPECT_LE(conformal<D>(P), largest * (1.0 + 1e-12));
    }
    Vec<D> s = Vec<D>::Ones();
    s[0] = K;
    EXPECT_NEAR(conformal<D>(Mat<D>(s.asDiagonal())), largest, 1e-12 * largest);
}

TEST(BoundedDistortionProjection, LargestConformalDistortionOnTheSet) {
    for (double K : {1.0, 2.0, 10.0}) {
        check_largest_conformal<2>(K);
        check_largest_conformal<3>(K);
    }
    EXPECT_DOUBLE_EQ(largest_conformal_distortion(10.0, 2), 5.05);
    EXPECT_EQ(largest_conformal_distortion(kInfinity, 3), kInfinity);
    EXPECT_THROW(largest_conformal_distortion(0.5, 2), InvalidArgumentError);
}

TEST(BoundedDistortionProjection, RejectsBadBounds) {
    EXPECT_THROW(project_bounded_distortion<2>(Mat<2>::Identity(), 0.5), InvalidArgumentError);
    EXPECT_THROW(project_bounded_distortion<2>(Mat<2>::Identity(), std::nan("")),
                 InvalidArgumentError);
    Mat<2> bad = Mat<2>::Identity();
    bad(0, 1) = kInfinity;
    EXPECT_THROW(project_bounded_distortion<2>(bad, 2.0), InvalidArgumentError);
}

}  // namespace
}  // namespace sa
