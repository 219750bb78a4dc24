#include <gtest/gtest.h>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <random>

#include "frontends/simplex_assembly/disassembly.h"
#include "optim/errors.h"
#include "tests/fixtures/random_matrices.h"

namespace sa {
namespace {

template <int D>
void check_closest() {
    std::mt19937 rng(D);
    for (int trial = 0; trial < 50; ++trial) {
        const Mat<D> A = gaussian_matrix<D>(rng);
        const Mat<D> R = closest_rotation<D>(A);
        EXPECT_TRUE((R.transpose() * R).isIdentity(1e-12));
        EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
        const Mat<D> S = closest_similarity<D>(A);
        EXPECT_NEAR(S.determinant(), std::pow((S.transpose() * S)(0, 0), D / 2.0), 1e-9);
        if (A.determinant() > 0) {
            // No other rotation is closer (probe with perturbed rotations).
            for (int k = 0; k < 20; ++k) {
                const Mat<D> other = closest_rotation<D>(R + 0.1 * gaussian_matrix<D>(rng));
                EXPECT_LE((A - R).norm(), (A - other).norm() + 1e-12);
            }
        }
    }
    // Fixed points: a rotation and a similarity project to themselves.
    const Mat<D> R = closest_rotation<D>(gaussian_matrix<D>(rng));
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

TEST(Disassembly, BoundedInitializationIsParsedWithItsBound) {
    const Initialization b = parse_initialization("bounded:10");
    EXPECT_EQ(b.kind, Initialization::Kind::kBoundedDistortion);
    EXPECT_EQ(b.bound, 10.0);
    EXPECT_EQ(b, Initialization::bounded_distortion(10.0));
    EXPECT_NE(b, Initialization::bounded_distortion(4.0));
    EXPECT_EQ(to_string(b), "bounded:10");
    EXPECT_EQ(to_string(parse_initialization("bounded:2.5")), "bounded:2.5");
    EXPECT_EQ(to_string(parse_initialization("bounded:inf")), "bounded:inf");
    EXPECT_EQ(parse_initialization("bounded:1").bound, 1.0);
    for (const Initialization i :
         {Initialization::kClosestSimilarity, Initialization::kClosestRotation,
          Initialization::kIdentity, Initialization::kRandomRotation,
          Initialization::bounded_distortion(1.0 / 3.0 + 3.0)}) {
        EXPECT_EQ(parse_initialization(to_string(i)), i) << to_string(i);
    }
    for (const char* bad : {"bounded", "bounded:", "bounded:0.5", "bounded:x", "bounded:3x",
                            "bounded:nan", "bounded:-2"}) {
        EXPECT_THROW(parse_initialization(bad), InvalidArgumentError) << bad;
    }
    EXPECT_THROW(Initialization::bounded_distortion(0.9), InvalidArgumentError);
}

TEST(Disassembly, BoundedProjectionOfEveryLinearPart) {
    // Figure 6(c): each A_i to sigma_max / sigma_min <= 10; inside ones unchanged, inverted ones
    // reflected, degenerate ones at the median scale.
    std::mt19937 rng(5);
    std::vector<Mat<3>> A(40);
    for (Mat<3>& a : A) a = gaussian_matrix<3>(rng);
    A[0] = Vec<3>(2.0, 1.0, 0.5).asDiagonal();    // inside
    A[1] = Mat<3>::Zero();                        // degenerate
    A[2] = Vec<3>(1.0, 1.0, -1e-9).asDiagonal();  // nearly flat and inverted
    const std::vector<Mat<3>> before = A;
    project_linear_parts<3>(A, Initialization::bounded_distortion(10.0));
    for (std::size_t i = 0; i < A.size(); ++i) {
        ASSERT_GT(A[i].determinant(), 0.0) << i;
        const Vec<3> s = Eigen::JacobiSVD<Mat<3>>(A[i]).singularValues();
        EXPECT_LE(s[0] / s[2], 10.0 * (1.0 + 1e-10)) << i;
    }
    EXPECT_EQ(A[0], before[0]);
    const Vec<3> s1 = Eigen::JacobiSVD<Mat<3>>(A[1]).singularValues();
    EXPECT_NEAR(s1[0], s1[2], 1e-12);  // a rotation at the median scale
    // K = inf: a flat simplex cannot keep its zero scale either.
    std::vector<Mat<2>> flat = {Mat<2>::Identity(), 2.0 * Mat<2>::Identity(),
                                Vec<2>(1.0, 0.0).asDiagonal()};
    project_linear_parts<2>(flat, Initialization::bounded_distortion(kInfinity));
    EXPECT_TRUE(flat[2].isApprox(2.0 * Mat<2>::Identity(), 1e-12)) << flat[2];
}

}  // namespace
}  // namespace sa
