#include <gtest/gtest.h>

#include <Eigen/LU>
#include <random>

#include "geometry/disassembly.h"
#include "optim/errors.h"

namespace sa {
namespace {

template <int D>
Mat<D> random_matrix(std::mt19937& rng) {
    std::normal_distribution<double> normal;
    Mat<D> A;
    for (int i = 0; i < D * D; ++i) A(i) = normal(rng);
    return A;
}

template <int D>
void check_closest() {
    std::mt19937 rng(D);
    for (int trial = 0; trial < 50; ++trial) {
        const Mat<D> A = random_matrix<D>(rng);
        const Mat<D> R = closest_rotation<D>(A);
        EXPECT_TRUE((R.transpose() * R).isIdentity(1e-12));
        EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
        const Mat<D> S = closest_similarity<D>(A);
        EXPECT_NEAR(S.determinant(), std::pow((S.transpose() * S)(0, 0), D / 2.0), 1e-9);
        if (A.determinant() > 0) {
            // No other rotation is closer (probe with perturbed rotations).
            for (int k = 0; k < 20; ++k) {
                const Mat<D> other = closest_rotation<D>(R + 0.1 * random_matrix<D>(rng));
                EXPECT_LE((A - R).norm(), (A - other).norm() + 1e-12);
            }
        }
    }
    // Fixed points: a rotation and a similarity project to themselves.
    const Mat<D> R = closest_rotation<D>(random_matrix<D>(rng));
    EXPECT_TRUE(closest_rotation<D>(R).isApprox(R, 1e-12));
    EXPECT_TRUE(closest_similarity<D>(2.5 * R).isApprox(2.5 * R, 1e-12));
}

TEST(Disassembly, ClosestRotationAndSimilarity) {
    check_closest<2>();
    check_closest<3>();
}

TEST(Disassembly, InvertedMatricesFlipTheirSmallestDirection) {
    Mat<2> A;
    A << 3.0, 0.0, 0.0, -0.5;  // a reflection of the small axis
    EXPECT_TRUE(closest_rotation<2>(A).isIdentity(1e-12));
    EXPECT_TRUE(closest_similarity<2>(A).isApprox(1.75 * Mat<2>::Identity(), 1e-12));
}

TEST(Disassembly, DegenerateScalesBecomeTheMedian) {
    std::vector<Mat<2>> A = {2.0 * Mat<2>::Identity(), 3.0 * Mat<2>::Identity(),
                             4.0 * Mat<2>::Identity(), Mat<2>::Zero()};
    project_linear_parts<2>(A, Initialization::kClosestSimilarity);
    EXPECT_TRUE(A[3].isApprox(3.0 * Mat<2>::Identity(), 1e-12));
    for (const Mat<2>& a : A) EXPECT_GT(a.determinant(), 0.0);
}

TEST(Disassembly, RandomRotationsAreRotationsAndSeeded) {
    std::vector<Mat<3>> a(10), b(10);
    project_linear_parts<3>(a, Initialization::kRandomRotation, 7);
    project_linear_parts<3>(b, Initialization::kRandomRotation, 7);
    for (int i = 0; i < 10; ++i) {
        EXPECT_NEAR(a[i].determinant(), 1.0, 1e-12);
        EXPECT_EQ(a[i], b[i]);
    }
    EXPECT_THROW(parse_initialization("closest"), InvalidArgumentError);
}

}  // namespace
}  // namespace sa
