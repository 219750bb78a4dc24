#include "energies/distortion_barrier.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "energies/simplex_energy.h"
#include "optim/derivative_check.h"

namespace sa {
namespace {

template <int D>
Mat<D> random_positive(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-0.3, 0.3);
    Mat<D> A = Mat<D>::Identity();
    for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) A(i, j) += u(rng);
    return A;
}

template <int D>
Vec<D * D> vec(const Mat<D>& A) {
    return Eigen::Map<const Vec<D * D>>(A.data());
}

// An anisotropic distortion a user might write: the symmetric Dirichlet energy of A M^-1, M a
// target metric. Not rotation-invariant: its Hessian takes the block projection.
struct Anisotropic {
    Mat<2> target_inverse = Eigen::Vector2d(1.0, 0.5).asDiagonal();
    template <class T>
    T operator()(const Eigen::Matrix<T, 2, 2>& A) const {
        const Eigen::Matrix<T, 2, 2> B = A * target_inverse;
        return 0.25 * (B.squaredNorm() + B.inverse().squaredNorm());
    }
};

TEST(DistortionBarrier, DerivativesMatchFiniteDifferences) {
    std::mt19937 rng(1);
    for (DistortionType type : {DistortionType::kConformal, DistortionType::kVolumetric,
                                DistortionType::kIsometric, DistortionType::kSymmetricDirichlet}) {
        const DistortionBarrier<2, BuiltinDistortion<2>> b2(BuiltinDistortion<2>(type), {8.0});
        const DistortionBarrier<3, BuiltinDistortion<3>> b3(BuiltinDistortion<3>(type), {});
        EXPECT_TRUE(check_derivatives(b2, 0, vec<2>(random_positive<2>(rng))).passes(1e-6))
            << to_string(type);
        EXPECT_TRUE(check_derivatives(b3, 0, vec<3>(random_positive<3>(rng))).passes(1e-6))
            << to_string(type);
    }
    const DistortionEnergy<2, Anisotropic> e({}, {2.5});
    EXPECT_TRUE(check_derivatives(e, 0, vec<2>(random_positive<2>(rng))).passes(1e-6));
}

TEST(DistortionBarrier, BuiltinDistortionEqualsTheSimplexEnergysBarrier) {
    std::mt19937 rng(2);
    for (DistortionType type :
         {DistortionType::kConformal, DistortionType::kVolumetric, DistortionType::kIsometric}) {
        SimplexEnergyOptions options;
        options.barrier_distortion = type;
        options.barrier.bound = 6.0;
        const SimplexEnergy<3> builtin(options, {1.0});
        const DistortionBarrier<3, BuiltinDistortion<3>> generic(BuiltinDistortion<3>(type),
                                                                 options.barrier);
        for (int k = 0; k < 5; ++k) {
            const Vec<9> a = vec<3>(random_positive<3>(rng));
            Vec<9> g1, g2;
            Mat<9> h1, h2;
            const double v1 = builtin.value_gradient_hessian(0, a, g1, h1);
            const double v2 = generic.value_gradient_hessian(0, a, g2, h2);
            EXPECT_NEAR(v1, v2, 1e-12 * v1);
            EXPECT_LT((g1 - g2).norm(), 1e-10 * g1.norm());
            EXPECT_LT((h1 - h2).norm(), 1e-10 * h1.norm());
            Mat<9> p1 = h1, p2 = h2;
            builtin.project_hessian(0, a, p1, ProjectionMode::kClamp, 1e-8);
            generic.project_hessian(0, a, p2, ProjectionMode::kClamp, 1e-8);
            EXPECT_LT((p1 - p2).norm(), 1e-9 * p1.norm());
        }
    }
    EXPECT_THROW(BuiltinDistortion<3>{DistortionType::kArap}, InvalidArgumentError);
}

TEST(DistortionBarrier, IsInfiniteAtAndBeyondItsBoundAndForInvertedMatrices) {
    const DistortionBarrier<2, BuiltinDistortion<2>> b(
        BuiltinDistortion<2>(DistortionType::kVolumetric), {1.25});  // det in (0.5, 2)
    EXPECT_TRUE(std::isfinite(b.value(0, vec<2>(Mat<2>::Identity()))));
    EXPECT_EQ(b.value(0, vec<2>(Mat<2>::Identity() * 1.5)), kInfinity);  // det 2.25
    Mat<2> flipped = Mat<2>::Identity();
    flipped(0, 0) = -1.0;
    EXPECT_EQ(b.value(0, vec<2>(flipped)), kInfinity);
    EXPECT_EQ(b.distortion(flipped), kInfinity);
    EXPECT_DOUBLE_EQ(b.with_bound(3.0).bound(), 3.0);
    // max_step: the orientation root. From I along -I the determinant vanishes at t = 1.
    EXPECT_NEAR(b.max_step(0, vec<2>(Mat<2>::Identity()), vec<2>(-Mat<2>::Identity())), 1.0, 1e-12);
    EXPECT_THROW((DistortionBarrier<2, Anisotropic>({}, {-1.0})), InvalidArgumentError);
}

TEST(DistortionBarrier, ProjectedHessiansArePositiveDefinite) {
    std::mt19937 rng(4);
    const DistortionBarrier<2, Anisotropic> b({}, {});
    for (int k = 0; k < 10; ++k) {
        const Vec<4> a = vec<2>(random_positive<2>(rng));
        Vec<4> g;
        Mat<4> h;
        b.value_gradient_hessian(0, a, g, h);
        b.project_hessian(0, a, h, ProjectionMode::kClamp, 1e-8);
        EXPECT_GE(Eigen::SelfAdjointEigenSolver<Mat<4>>(h).eigenvalues().minCoeff(), 1e-8 * 0.99);
    }
}

}  // namespace
}  // namespace sa
