#include "frontends/polycube/tet_angle_barriers.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <random>

#include "optim/derivative_check.h"

namespace sa {
namespace {

constexpr double kDegree = M_PI / 180.0;

// A fan of tetrahedra around the edge p = 0, q = (0, 0, 1): ring vertex m on the unit circle at
// angle degrees[m] (at height heights[m]); tetrahedron k is (p, q, ring k, ring k + 1).
Eigen::VectorXd fan_positions(const std::vector<double>& degrees,
                              const std::vector<double>& heights) {
    const int M = int(degrees.size());
    Eigen::VectorXd x = Eigen::VectorXd::Zero(3 * M + 6);
    x.segment<3>(3) = Vec<3>(0, 0, 1);
    for (int m = 0; m < M; ++m) {
        x.segment<3>(6 + 3 * m) =
            Vec<3>(std::cos(degrees[m] * kDegree), std::sin(degrees[m] * kDegree), heights[m]);
    }
    return x;
}

/// The vertex-form barrier of one fan of M - 1 tetrahedra around an edge, ring vertices in order.
DihedralSumVertexEnergy chain_fan(int M) {
    DihedralSumVertexEnergy energy;
    energy.tets.emplace_back();
    for (int k = 0; k + 1 < M; ++k) energy.tets[0].push_back({k, k + 1});
    return energy;
}

Vec<3> unit(double degrees) {
    return Vec<3>(std::cos(degrees * kDegree), std::sin(degrees * kDegree), 0.0);
}

/// The star of a boundary vertex made of two tetrahedra, quarter-spaces side by side (solid
/// angle sum pi at rest), in A-form.
SolidAngleSumEnergy two_tet_star() {
    SolidAngleSumEnergy solid;
    solid.stars.push_back({{Vec<3>(1, 0, 0), Vec<3>(0, 1, 0), Vec<3>(0, 0, 1)},
                           {Vec<3>(0, 1, 0), Vec<3>(-1, 0, 0), Vec<3>(0, 0, 1)}});
    return solid;
}

/// vec(I) for each of K tetrahedra: the rest map in A-form.
Eigen::VectorXd identity_parts(int K) {
    Eigen::VectorXd identity(9 * K);
    for (int k = 0; k < K; ++k)
        identity.segment<9>(9 * k) = Eigen::Map<const Vec<9>>(Mat<3>::Identity().eval().data());
    return identity;
}

/// The element Hessian of an A-form barrier (its diagonal 9 x 9 blocks side by side) as the
/// dense matrix it stands for, zero off the blocks.
Eigen::MatrixXd dense(const Eigen::MatrixXd& blocks) {
    const Eigen::Index n = blocks.cols();
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index k = 0; k < n / 9; ++k)
        h.block(9 * k, 9 * k, 9, 9) = blocks.middleCols(9 * k, 9);
    return h;
}

double smallest_eigenvalue(const Eigen::MatrixXd& h) {
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(h).eigenvalues().minCoeff();
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
    const auto energy = chain_fan(5);
    const Eigen::VectorXd x = fan_positions({0, 80, 160, 240, 320}, {0, 0, 0, 0, 0});
    EXPECT_NEAR(energy.angle_sum(0, x), 320.0 * kDegree, 1e-13);
    EXPECT_NEAR(energy.value(0, x), 1.0 / (40.0 * kDegree), 1e-12);
    // One more tetrahedron of 80 degrees: 400 degrees, the fan overlaps itself.
    const auto six = chain_fan(6);
    const Eigen::VectorXd over = fan_positions({0, 80, 160, 240, 320, 400}, {0, 0, 0, 0, 0, 0.5});
    EXPECT_NEAR(six.angle_sum(0, over), 400.0 * kDegree, 1e-13);
    EXPECT_EQ(six.value(0, over), kInfinity);
}

TEST(TetAngleBarriers, SolidAngleSumOfAFlatBoundaryIsTwoPi) {
    // v at the origin on the plane z = 0, a ring of 6 vertices around it in the plane and one
    // below: six tetrahedra fill the half space under v's neighbourhood.
    SolidAngleSumVertexEnergy energy;
    energy.tets.emplace_back();
    for (int k = 0; k < 6; ++k) energy.tets[0].push_back({(k + 1) % 6, k, 6});
    Eigen::VectorXd x = Eigen::VectorXd::Zero(24);
    for (int k = 0; k < 6; ++k) x.segment<3>(3 + 3 * k) = unit(60.0 * k);
    x.segment<3>(21) = Vec<3>(0.1, -0.2, -1.0);
    EXPECT_NEAR(energy.angle_sum(0, x), 2 * M_PI, 1e-13);
    EXPECT_NEAR(energy.value(0, x), 1.0 / (2 * M_PI), 1e-13);
}

template <class E>
void expect_derivatives(const E& energy, const Eigen::VectorXd& x) {
    const DerivativeCheck check = check_derivatives(energy, 0, x);
    EXPECT_TRUE(std::isfinite(check.value));
    EXPECT_TRUE(check.passes(1e-6))
        << check.gradient_error << " " << check.hessian_error << " " << check.asymmetry;
    // The gradient of the angle sum, against central differences.
    Eigen::VectorXd g;
    energy.angle_sum(0, x, &g);
    for (Eigen::Index i = 0; i < x.size(); ++i) {
        Eigen::VectorXd xp = x, xm = x;
        xp[i] += 1e-6;
        xm[i] -= 1e-6;
        EXPECT_NEAR(g[i], (energy.angle_sum(0, xp) - energy.angle_sum(0, xm)) / 2e-6, 1e-6);
    }
}

Eigen::VectorXd perturbed(Eigen::VectorXd x, unsigned seed, double size) {
    std::mt19937 random(seed);
    std::normal_distribution<double> normal(0.0, size);
    for (Eigen::Index i = 0; i < x.size(); ++i) x[i] += normal(random);
    return x;
}

TEST(TetAngleBarriers, VertexFormDerivativesMatchFiniteDifferences) {
    const auto dihedral = chain_fan(5);
    for (const unsigned seed : {1u, 2u, 3u}) {
        expect_derivatives(
            dihedral, perturbed(fan_positions({0, 70, 150, 230, 300}, {0.1, -0.2, 0.3, 0.0, 0.2}),
                                seed, 0.05));
    }
    SolidAngleSumVertexEnergy solid;
    solid.tets.emplace_back();
    for (int k = 0; k < 6; ++k) solid.tets[0].push_back({(k + 1) % 6, k, 6});
    Eigen::VectorXd x = Eigen::VectorXd::Zero(24);
    for (int k = 0; k < 6; ++k) x.segment<3>(3 + 3 * k) = unit(60.0 * k) + Vec<3>(0, 0, 0.3);
    x.segment<3>(21) = Vec<3>(0.1, -0.2, -1.0);
    for (const unsigned seed : {4u, 5u}) expect_derivatives(solid, perturbed(x, seed, 0.05));
}

// A-form: tetrahedron k's linear part maps its rest vectors onto the fan's; the values equal the
// vertex form's, and the derivatives match finite differences.
TEST(TetAngleBarriers, AFormAgreesWithTheVertexFormAndHasItsDerivatives) {
    std::mt19937 random(11);
    std::normal_distribution<double> normal(0.0, 0.2);
    const auto vertex_form = chain_fan(4);
    const Eigen::VectorXd x = fan_positions({0, 90, 170, 260}, {0.2, -0.1, 0.1, 0.0});
    DihedralSumEnergy a_form;
    a_form.fans.emplace_back(3);
    Eigen::VectorXd a(27);
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

    const SolidAngleSumEnergy solid = two_tet_star();
    const Eigen::VectorXd identity = identity_parts(2);
    EXPECT_NEAR(solid.angle_sum(0, identity), M_PI, 1e-14);
    expect_derivatives(solid, perturbed(identity, 7, 0.1));
}

// The A-forms on fans and stars of 3 to 40 tetrahedra (up to 360 variables): finite values and
// derivatives that match finite differences.
TEST(TetAngleBarriers, AFormsOnFansAndStarsOfAnySize) {
    for (const int K : {3, 14, 15, 31, 40}) {
        // Around the edge (0, 0, 1) and around the vertex 0, ring points over 330 degrees.
        DihedralSumEnergy fan;
        SolidAngleSumEnergy star;
        fan.fans.emplace_back();
        star.stars.emplace_back();
        for (int k = 0; k < K; ++k) {
            const Vec<3> u = unit(330.0 * k / K), w = unit(330.0 * (k + 1) / K);
            fan.fans[0].push_back({Vec<3>(0, 0, 1), u, w});
            star.stars[0].push_back({w, u, Vec<3>(0, 0, -1)});  // det[w, u, -z] > 0
        }
        const Eigen::VectorXd a = perturbed(identity_parts(K), unsigned(K), 0.01);
        expect_derivatives(fan, a);
        expect_derivatives(star, a);
        EXPECT_NEAR(fan.angle_sum(0, identity_parts(K)), 330.0 * kDegree, 1e-12) << K;
        EXPECT_NEAR(star.angle_sum(0, identity_parts(K)), 330.0 / 360.0 * 2 * M_PI, 1e-12) << K;
    }
}

TEST(TetAngleBarriers, ProjectedHessianIsPositiveSemidefinite) {
    const auto energy = chain_fan(5);
    for (const unsigned seed : {1u, 2u, 3u, 4u}) {
        const Eigen::VectorXd x =
            perturbed(fan_positions({0, 80, 160, 240, 330}, {0, 0, 0, 0, 0}), seed, 0.1);
        Eigen::VectorXd g(21);
        Eigen::MatrixXd h(21, 21);
        ASSERT_TRUE(std::isfinite(energy.value_gradient_hessian(0, x, g, h)));
        const double raw = smallest_eigenvalue(h);
        Eigen::MatrixXd projected = h;
        const bool changed = energy.project_hessian(0, x, projected, ProjectionMode::kClamp, 1e-9);
        const double smallest = smallest_eigenvalue(projected);
        EXPECT_GE(smallest, -1e-9 * projected.norm()) << seed;
        if (raw < -1e-9 * h.norm()) {
            EXPECT_TRUE(changed);
        }
    }
}

// In A-form the Hessian is block diagonal (one 9 x 9 block per tetrahedron, the only part
// assembled), and the projection majorizes the barrier's curvature along its gradient: with
// E' = E^2 and E'' = 2 E^3, projected - (2 / E) g g^T = (majorizer - rank-one term) + (projected
// angle blocks) is positive semidefinite although the blocks drop the rank-one term's coupling.
TEST(TetAngleBarriers, AFormProjectionIsABlockDiagonalMajorizer) {
    const SolidAngleSumEnergy solid = two_tet_star();
    static_assert(SolidAngleSumEnergy::hessian_block == 9);
    const Eigen::VectorXd identity = identity_parts(2);
    for (const unsigned seed : {1u, 2u, 3u}) {
        const Eigen::VectorXd x = perturbed(identity, seed, 0.2);
        Eigen::VectorXd g(18);
        Eigen::MatrixXd h(9, 18);
        const double e = solid.value_gradient_hessian(0, x, g, h);
        ASSERT_TRUE(std::isfinite(e));
        Eigen::MatrixXd projected = h;
        EXPECT_TRUE(solid.project_hessian(0, x, projected, ProjectionMode::kClamp, 1e-9));
        const Eigen::MatrixXd rest = dense(projected) - (2.0 / e) * g * g.transpose();
        EXPECT_GE(smallest_eigenvalue(rest), -1e-9 * projected.norm()) << seed;
    }
}

// The projection is computed from x, but the Hessian it replaces carries the term's weight:
// projecting w H (with w epsilon) gives w times the projection of H, in A-form (block diagonal)
// and in vertex form (dense).
TEST(TetAngleBarriers, ProjectionKeepsTheTermsWeight) {
    const SolidAngleSumEnergy solid = two_tet_star();
    const Eigen::VectorXd x = perturbed(identity_parts(2), 5, 0.2);
    Eigen::VectorXd g(18);
    Eigen::MatrixXd h(9, 18);
    ASSERT_TRUE(std::isfinite(solid.value_gradient_hessian(0, x, g, h)));
    Eigen::MatrixXd once = h, thrice = 3.0 * h;
    ASSERT_TRUE(solid.project_hessian(0, x, once, ProjectionMode::kClamp, 1e-9));
    ASSERT_TRUE(solid.project_hessian(0, x, thrice, ProjectionMode::kClamp, 3e-9));
    EXPECT_LT((thrice - 3.0 * once).norm(), 1e-10 * thrice.norm());

    const auto fan = chain_fan(5);
    const Eigen::VectorXd y =
        perturbed(fan_positions({0, 80, 160, 240, 330}, {0, 0, 0, 0, 0}), 2, 0.1);
    Eigen::VectorXd gy(21);
    Eigen::MatrixXd hy(21, 21);
    ASSERT_TRUE(std::isfinite(fan.value_gradient_hessian(0, y, gy, hy)));
    Eigen::MatrixXd one = hy, half = 0.5 * hy;
    const bool projected = fan.project_hessian(0, y, one, ProjectionMode::kClamp, 1e-9);
    EXPECT_EQ(fan.project_hessian(0, y, half, ProjectionMode::kClamp, 0.5e-9), projected);
    EXPECT_LT((half - 0.5 * one).norm(), 1e-10 * one.norm());
}

// A fan around a boundary edge that overlaps itself (theta = 400 degrees): a descent on theta
// along its gradient brings it below 2 pi; from there, descending the barrier plus a pull back to
// the overlapping positions keeps it below 2 pi, E finite and decreasing, however hard the pull.
TEST(TetAngleBarriers, AnOverlappingFanIsBroughtBelowTwoPiAndKeptThere) {
    const auto energy = chain_fan(6);
    const Eigen::VectorXd folded = fan_positions({0, 80, 160, 240, 320, 400}, {0, 0, 0, 0, 0, 0.5});
    Eigen::VectorXd x = folded;
    ASSERT_GT(energy.angle_sum(0, x), 2 * M_PI);
    // Ring vertices only: the edge stays.
    auto ring_only = [](Eigen::VectorXd v) {
        v.head<6>().setZero();
        return v;
    };
    int steps = 0;
    for (; energy.angle_sum(0, x) >= 2 * M_PI - 0.1 && steps < 100; ++steps) {
        Eigen::VectorXd g;
        const double theta = energy.angle_sum(0, x, &g);
        g = ring_only(g);
        // A Gauss-Newton step on theta towards 2 pi - 0.2, at most 0.1 long.
        Eigen::VectorXd step = -(theta - (2 * M_PI - 0.2)) / g.squaredNorm() * g;
        if (step.norm() > 0.1) step *= 0.1 / step.norm();
        x += step;
    }
    EXPECT_LT(steps, 100);
    EXPECT_LT(energy.angle_sum(0, x), 2 * M_PI);
    ASSERT_TRUE(std::isfinite(energy.value(0, x)));

    const double pull = 100.0;
    auto total = [&](const Eigen::VectorXd& y) {
        return energy.value(0, y) + pull * (y - folded).squaredNorm();
    };
    double previous = total(x);
    for (int iteration = 0; iteration < 300; ++iteration) {
        Eigen::VectorXd g(24);
        Eigen::MatrixXd h(24, 24);
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
