#include "energies/tet_angle_barriers.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "optim/derivative_check.h"

namespace sa {
namespace {

constexpr double kDegree = M_PI / 180.0;

// A fan of tetrahedra around the edge p = 0, q = (0, 0, 1): ring vertex m on the unit circle at
// angle degrees[m] (at height heights[m]); tetrahedron k is (p, q, ring k, ring k + 1).
template <int M>
Vec<3 * M + 6> fan_positions(const std::array<double, M>& degrees,
                             const std::array<double, M>& heights) {
    Vec<3 * M + 6> x = Vec<3 * M + 6>::Zero();
    x.template segment<3>(3) = Vec<3>(0, 0, 1);
    for (int m = 0; m < M; ++m) {
        x.template segment<3>(6 + 3 * m) =
            Vec<3>(std::cos(degrees[m] * kDegree), std::sin(degrees[m] * kDegree), heights[m]);
    }
    return x;
}

template <int M>
DihedralSumVertexEnergy<M> chain_fan() {
    DihedralSumVertexEnergy<M> energy;
    energy.tets.emplace_back();
    for (int k = 0; k + 1 < M; ++k) energy.tets[0].push_back({k, k + 1});
    return energy;
}

Vec<3> unit(double degrees) {
    return Vec<3>(std::cos(degrees * kDegree), std::sin(degrees * kDegree), 0.0);
}

/// The star of a boundary vertex made of two tetrahedra, quarter-spaces side by side (solid
/// angle sum pi at rest), in A-form.
SolidAngleSumEnergy<2> two_tet_star() {
    SolidAngleSumEnergy<2> solid;
    solid.stars.emplace_back();
    solid.stars[0][0] = {Vec<3>(1, 0, 0), Vec<3>(0, 1, 0), Vec<3>(0, 0, 1)};
    solid.stars[0][1] = {Vec<3>(0, 1, 0), Vec<3>(-1, 0, 0), Vec<3>(0, 0, 1)};
    return solid;
}

/// vec(I) for each of K tetrahedra: the rest map in A-form.
template <int K>
Vec<9 * K> identity_parts() {
    Vec<9 * K> identity;
    for (int k = 0; k < K; ++k)
        identity.template segment<9>(9 * k) =
            Eigen::Map<const Vec<9>>(Mat<3>::Identity().eval().data());
    return identity;
}

TEST(TetAngleBarriers, AnglesOfKnownTetrahedra) {
    bool defined = true;
    const Vec<3> x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    EXPECT_NEAR(dihedral_angle<double>(z, x, y, &defined), M_PI / 2, 1e-15);
    EXPECT_NEAR(dihedral_angle<double>(z, y, x, &defined), -M_PI / 2, 1e-15);  // inverted
    EXPECT_NEAR(dihedral_angle<double>(z, x, unit(135.0) + 0.3 * z, &defined), 135.0 * kDegree,
                1e-14);
    EXPECT_NEAR(solid_angle<double>(x, y, z, &defined), M_PI / 2, 1e-15);
    EXPECT_NEAR(solid_angle<double>(x, z, y, &defined), -M_PI / 2, 1e-15);
    // The regular tetrahedron: dihedral acos(1/3), solid angle acos(23/27).
    const Vec<3> a(1, 1, 1), b(1, -1, -1), c(-1, -1, 1), d(-1, 1, -1);
    ASSERT_GT((b - a).dot((c - a).cross(d - a)), 0.0);
    EXPECT_NEAR(dihedral_angle<double>(b - a, c - a, d - a, &defined), std::acos(1.0 / 3.0), 1e-14);
    EXPECT_NEAR(solid_angle<double>(b - a, c - a, d - a, &defined), std::acos(23.0 / 27.0), 1e-14);
    EXPECT_TRUE(defined);
    // Beyond pi (where atan2's denominator is negative): a flat cone just under a half space.
    const double wide = solid_angle<double>(unit(0.0) - 0.01 * z, unit(240.0) - 0.01 * z,
                                            unit(120.0) - 0.01 * z, &defined);
    EXPECT_GT(wide, 6.1);
    EXPECT_LT(wide, 2 * M_PI);
    dihedral_angle<double>(z, 2.0 * z, x, &defined);
    EXPECT_FALSE(defined);
    solid_angle<double>(x, Vec<3>::Zero(), z, &defined);
    EXPECT_FALSE(defined);
}

TEST(TetAngleBarriers, DihedralSumIsOneOverTheGapTo2Pi) {
    const auto energy = chain_fan<5>();
    const Vec<21> x = fan_positions<5>({0, 80, 160, 240, 320}, {0, 0, 0, 0, 0});
    EXPECT_NEAR(energy.angle_sum(0, x), 320.0 * kDegree, 1e-13);
    EXPECT_NEAR(energy.value(0, x), 1.0 / (40.0 * kDegree), 1e-12);
    // One more tetrahedron of 80 degrees: 400 degrees, the fan overlaps itself.
    const auto six = chain_fan<6>();
    const Vec<24> over = fan_positions<6>({0, 80, 160, 240, 320, 400}, {0, 0, 0, 0, 0, 0.5});
    EXPECT_NEAR(six.angle_sum(0, over), 400.0 * kDegree, 1e-13);
    EXPECT_EQ(six.value(0, over), kInfinity);
}

TEST(TetAngleBarriers, SolidAngleSumOfAFlatBoundaryIsTwoPi) {
    // v at the origin on the plane z = 0, a ring of 6 vertices around it in the plane and one
    // below: six tetrahedra fill the half space under v's neighbourhood.
    SolidAngleSumVertexEnergy<7> energy;
    energy.tets.emplace_back();
    for (int k = 0; k < 6; ++k) energy.tets[0].push_back({(k + 1) % 6, k, 6});
    Vec<24> x = Vec<24>::Zero();
    for (int k = 0; k < 6; ++k) x.segment<3>(3 + 3 * k) = unit(60.0 * k);
    x.segment<3>(21) = Vec<3>(0.1, -0.2, -1.0);
    EXPECT_NEAR(energy.angle_sum(0, x), 2 * M_PI, 1e-13);
    EXPECT_NEAR(energy.value(0, x), 1.0 / (2 * M_PI), 1e-13);
}

template <class E>
void expect_derivatives(const E& energy, const Vec<E::arity>& x) {
    const DerivativeCheck check = check_derivatives(energy, 0, x);
    EXPECT_TRUE(std::isfinite(check.value));
    EXPECT_TRUE(check.passes(1e-6))
        << check.gradient_error << " " << check.hessian_error << " " << check.asymmetry;
    // The gradient of the angle sum, against central differences.
    Vec<E::arity> g;
    energy.angle_sum(0, x, &g);
    for (int i = 0; i < E::arity; ++i) {
        Vec<E::arity> xp = x, xm = x;
        xp[i] += 1e-6;
        xm[i] -= 1e-6;
        EXPECT_NEAR(g[i], (energy.angle_sum(0, xp) - energy.angle_sum(0, xm)) / 2e-6, 1e-6);
    }
}

template <int N>
Vec<N> perturbed(Vec<N> x, unsigned seed, double size) {
    std::mt19937 random(seed);
    std::normal_distribution<double> normal(0.0, size);
    for (int i = 0; i < N; ++i) x[i] += normal(random);
    return x;
}

TEST(TetAngleBarriers, VertexFormDerivativesMatchFiniteDifferences) {
    const auto dihedral = chain_fan<5>();
    for (const unsigned seed : {1u, 2u, 3u}) {
        expect_derivatives(dihedral, perturbed(fan_positions<5>({0, 70, 150, 230, 300},
                                                                {0.1, -0.2, 0.3, 0.0, 0.2}),
                                               seed, 0.05));
    }
    SolidAngleSumVertexEnergy<7> solid;
    solid.tets.emplace_back();
    for (int k = 0; k < 6; ++k) solid.tets[0].push_back({(k + 1) % 6, k, 6});
    Vec<24> x = Vec<24>::Zero();
    for (int k = 0; k < 6; ++k) x.segment<3>(3 + 3 * k) = unit(60.0 * k) + Vec<3>(0, 0, 0.3);
    x.segment<3>(21) = Vec<3>(0.1, -0.2, -1.0);
    for (const unsigned seed : {4u, 5u}) expect_derivatives(solid, perturbed(x, seed, 0.05));
}

// A-form: tetrahedron k's linear part maps its rest vectors onto the fan's; the values equal the
// vertex form's, and the derivatives match finite differences.
TEST(TetAngleBarriers, AFormAgreesWithTheVertexFormAndHasItsDerivatives) {
    std::mt19937 random(11);
    std::normal_distribution<double> normal(0.0, 0.2);
    const auto vertex_form = chain_fan<4>();
    const Vec<18> x = fan_positions<4>({0, 90, 170, 260}, {0.2, -0.1, 0.1, 0.0});
    DihedralSumEnergy<3> a_form;
    a_form.fans.emplace_back();
    Vec<27> a;
    for (int k = 0; k < 3; ++k) {
        Eigen::Matrix3d rest;  // arbitrary rest vectors (columns edge, u, w), positive
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) rest(i, j) = (i == j ? 1.0 : 0.0) + normal(random);
        }
        if (rest.determinant() < 0) rest.col(1).swap(rest.col(2));
        a_form.fans[0][k] = {rest.col(0), rest.col(1), rest.col(2)};
        Eigen::Matrix3d image;
        image.col(0) = x.segment<3>(3) - x.segment<3>(0);
        image.col(1) = x.segment<3>(6 + 3 * k) - x.segment<3>(0);
        image.col(2) = x.segment<3>(9 + 3 * k) - x.segment<3>(0);
        const Eigen::Matrix3d A = image * rest.inverse();
        a.segment<9>(9 * k) = Eigen::Map<const Vec<9>>(A.data());
    }
    EXPECT_NEAR(a_form.value(0, a), vertex_form.value(0, x), 1e-12);
    expect_derivatives(a_form, perturbed(a, 6, 0.02));

    const SolidAngleSumEnergy<2> solid = two_tet_star();
    const Vec<18> identity = identity_parts<2>();
    EXPECT_NEAR(solid.angle_sum(0, identity), M_PI, 1e-14);
    expect_derivatives(solid, perturbed(identity, 7, 0.1));
}

TEST(TetAngleBarriers, ProjectedHessianIsPositiveSemidefinite) {
    const auto energy = chain_fan<5>();
    for (const unsigned seed : {1u, 2u, 3u, 4u}) {
        const Vec<21> x =
            perturbed(fan_positions<5>({0, 80, 160, 240, 330}, {0, 0, 0, 0, 0}), seed, 0.1);
        Vec<21> g;
        Mat<21> h;
        ASSERT_TRUE(std::isfinite(energy.value_gradient_hessian(0, x, g, h)));
        const double raw = Eigen::SelfAdjointEigenSolver<Mat<21>>(h).eigenvalues().minCoeff();
        Mat<21> projected = h;
        const bool changed = energy.project_hessian(0, x, projected, ProjectionMode::kClamp, 1e-9);
        const double smallest =
            Eigen::SelfAdjointEigenSolver<Mat<21>>(projected).eigenvalues().minCoeff();
        EXPECT_GE(smallest, -1e-9 * projected.norm()) << seed;
        if (raw < -1e-9 * h.norm()) {
            EXPECT_TRUE(changed);
        }
    }
}

// In A-form the projected Hessian is block diagonal (one 9 x 9 block per tetrahedron, the only
// part assembled) and majorizes the barrier's curvature along its gradient: with E' = E^2 and
// E'' = 2 E^3, projected - (2 / E) g g^T = (majorizer - rank-one term) + (projected angle
// blocks) is positive semidefinite.
TEST(TetAngleBarriers, AFormProjectionIsABlockDiagonalMajorizer) {
    const SolidAngleSumEnergy<2> solid = two_tet_star();
    static_assert(SolidAngleSumEnergy<2>::hessian_block == 9);
    const Vec<18> identity = identity_parts<2>();
    for (const unsigned seed : {1u, 2u, 3u}) {
        const Vec<18> x = perturbed(identity, seed, 0.2);
        Vec<18> g;
        Mat<18> h;
        const double e = solid.value_gradient_hessian(0, x, g, h);
        ASSERT_TRUE(std::isfinite(e));
        EXPECT_GT((h.block<9, 9>(9, 0).cwiseAbs().maxCoeff()), 0.0);  // the exact one couples
        Mat<18> projected = h;
        EXPECT_TRUE(solid.project_hessian(0, x, projected, ProjectionMode::kClamp, 1e-9));
        EXPECT_EQ((projected.block<9, 9>(9, 0).cwiseAbs().maxCoeff()), 0.0) << seed;
        EXPECT_EQ((projected.block<9, 9>(0, 9).cwiseAbs().maxCoeff()), 0.0) << seed;
        const Mat<18> rest = projected - (2.0 / e) * g * g.transpose();
        EXPECT_GE(Eigen::SelfAdjointEigenSolver<Mat<18>>(rest).eigenvalues().minCoeff(),
                  -1e-9 * projected.norm())
            << seed;
    }
}

// The projection is computed from x, but the Hessian it replaces carries the term's weight:
// projecting w H (with w epsilon) gives w times the projection of H, in A-form (block diagonal)
// and in vertex form (dense).
TEST(TetAngleBarriers, ProjectionKeepsTheTermsWeight) {
    const SolidAngleSumEnergy<2> solid = two_tet_star();
    const Vec<18> identity = identity_parts<2>();
    const Vec<18> x = perturbed(identity, 5, 0.2);
    Vec<18> g;
    Mat<18> h;
    ASSERT_TRUE(std::isfinite(solid.value_gradient_hessian(0, x, g, h)));
    for (int k = 0; k < 2; ++k) {  // what the assembler's slots keep: the diagonal blocks
        const int other = 9 * (1 - k);
        h.block<9, 9>(9 * k, other).setZero();
    }
    Mat<18> once = h, thrice = 3.0 * h;
    ASSERT_TRUE(solid.project_hessian(0, x, once, ProjectionMode::kClamp, 1e-9));
    ASSERT_TRUE(solid.project_hessian(0, x, thrice, ProjectionMode::kClamp, 3e-9));
    EXPECT_LT((thrice - 3.0 * once).norm(), 1e-10 * thrice.norm());

    const auto fan = chain_fan<5>();
    const Vec<21> y = perturbed(fan_positions<5>({0, 80, 160, 240, 330}, {0, 0, 0, 0, 0}), 2, 0.1);
    Vec<21> gy;
    Mat<21> hy;
    ASSERT_TRUE(std::isfinite(fan.value_gradient_hessian(0, y, gy, hy)));
    Mat<21> one = hy, half = 0.5 * hy;
    const bool projected = fan.project_hessian(0, y, one, ProjectionMode::kClamp, 1e-9);
    EXPECT_EQ(fan.project_hessian(0, y, half, ProjectionMode::kClamp, 0.5e-9), projected);
    EXPECT_LT((half - 0.5 * one).norm(), 1e-10 * one.norm());
}

// A fan around a boundary edge that overlaps itself (theta = 400 degrees): a descent on theta
// along its gradient brings it below 2 pi; from there, descending the barrier plus a pull back to
// the overlapping positions keeps it below 2 pi, E finite and decreasing, however hard the pull.
TEST(TetAngleBarriers, AnOverlappingFanIsBroughtBelowTwoPiAndKeptThere) {
    const auto energy = chain_fan<6>();
    const Vec<24> folded = fan_positions<6>({0, 80, 160, 240, 320, 400}, {0, 0, 0, 0, 0, 0.5});
    Vec<24> x = folded;
    ASSERT_GT(energy.angle_sum(0, x), 2 * M_PI);
    // Ring vertices only: the edge stays.
    auto ring_only = [](Vec<24> v) {
        v.head<6>().setZero();
        return v;
    };
    int steps = 0;
    for (; energy.angle_sum(0, x) >= 2 * M_PI - 0.1 && steps < 100; ++steps) {
        Vec<24> g;
        const double theta = energy.angle_sum(0, x, &g);
        g = ring_only(g);
        // A Gauss-Newton step on theta towards 2 pi - 0.2, at most 0.1 long.
        Vec<24> step = -(theta - (2 * M_PI - 0.2)) / g.squaredNorm() * g;
        if (step.norm() > 0.1) step *= 0.1 / step.norm();
        x += step;
    }
    EXPECT_LT(steps, 100);
    EXPECT_LT(energy.angle_sum(0, x), 2 * M_PI);
    ASSERT_TRUE(std::isfinite(energy.value(0, x)));

    const double pull = 100.0;
    auto total = [&](const Vec<24>& y) {
        return energy.value(0, y) + pull * (y - folded).squaredNorm();
    };
    double previous = total(x);
    for (int iteration = 0; iteration < 300; ++iteration) {
        Vec<24> g;
        Mat<24> h;
        energy.value_gradient_hessian(0, x, g, h);
        g = ring_only(g + 2.0 * pull * (x - folded));
        double t = 1e-3;
        while (!(total(x - t * g) < previous) && t > 1e-16) t *= 0.5;  // +inf is rejected
        if (t <= 1e-16) break;
        x -= t * g;
        const double now = total(x);
        EXPECT_LE(now, previous);
        previous = now;
        EXPECT_LT(energy.angle_sum(0, x), 2 * M_PI);
    }
    EXPECT_LT(energy.angle_sum(0, x), 2 * M_PI);
    EXPECT_GT(energy.angle_sum(0, x), 2 * M_PI - 0.2);  // the pull took it up to the barrier
}

}  // namespace
}  // namespace sa
