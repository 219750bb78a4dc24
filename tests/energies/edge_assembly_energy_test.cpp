#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "energies/affine_point_energies.h"
#include "energies/edge_assembly_energy.h"
#include "energies/polynomial_roots.h"
#include "energies/vertex_copy_energies.h"
#include "optim/derivative_check.h"

namespace sa {
namespace {

template <int N>
Vec<N> random_vector(std::mt19937& rng) {
    std::normal_distribution<double> normal;
    Vec<N> v;
    for (int i = 0; i < N; ++i) v[i] = normal(rng);
    return v;
}

TEST(AssemblyEnergies, DerivativesMatchFiniteDifferences) {
    std::mt19937 rng(3);
    SharedFacetEdges<2> f2;
    f2.in_i = Vec<2>(0.6, 0.8);
    f2.in_j = Vec<2>(1.0, 0.0);                                     // another frame
    f2.rotation = Eigen::Rotation2Dd(M_PI / 2).toRotationMatrix();  // a frame-field matching
    SharedFacetEdges<3> f3;
    f3.in_i = Eigen::Matrix3d::Identity();
    f3.in_j << 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0;
    EXPECT_TRUE(
        check_derivatives(EdgeAssemblyEnergy<2>({f2}), 0, random_vector<8>(rng)).passes(1e-7));
    EXPECT_TRUE(
        check_derivatives(EdgeAssemblyEnergy<3>({f3}), 0, random_vector<18>(rng)).passes(1e-7));

    const AffinePointAgreementEnergy<3> agree({{Vec<3>(0.1, 0.2, 0.3), Vec<3>(-0.3, 0.0, 0.2)}});
    EXPECT_TRUE(check_derivatives(agree, 0, random_vector<24>(rng)).passes(1e-7));
    const AffinePointTargetEnergy<2> target({{Vec<2>(0.1, -0.4), Vec<2>(2.0, 1.0)}});
    EXPECT_TRUE(check_derivatives(target, 0, random_vector<6>(rng)).passes(1e-7));
    EXPECT_TRUE(
        check_derivatives(VertexCopyAgreementEnergy<3>{}, 0, random_vector<6>(rng)).passes(1e-7));
}

TEST(EdgeAssemblyEnergy, IsZeroExactlyWhenTheSharedEdgesAgree) {
    const Vec<2> e = Vec<2>(3.0, 4.0).normalized();
    SharedFacetEdges<2> facet;
    facet.in_i = facet.in_j = e;
    const EdgeAssemblyEnergy<2> energy({facet});
    Mat<2> Ai, Aj;
    Ai << 1.0, 2.0, 0.5, 3.0;
    Aj = Ai + Vec<2>(0.7, -0.2) * Vec<2>(-4.0, 3.0).transpose();  // differs only across the edge
    Vec<8> x;
    x.head<4>() = Eigen::Map<const Vec<4>>(Ai.data());
    x.tail<4>() = Eigen::Map<const Vec<4>>(Aj.data());
    EXPECT_NEAR(energy.value(0, x), 0.0, 1e-14);
    x[4] += 0.1;  // Aj(0, 0): now |dA e|^2 = (0.1 * 3/5)^2
    EXPECT_NEAR(energy.value(0, x), std::pow(0.1 * 3.0 / 5.0, 2), 1e-15);
}

TEST(VertexSimplexEnergy, MatchesTheEnergyOfTheAffineMap) {
    // Rest triangle and a mapped copy: A = P R^-1 must reproduce the SimplexEnergy value.
    Mat<2> R;
    R << 1.0, 0.2, 0.0, 0.9;
    const SimplexEnergy<2> inner(SimplexEnergyOptions{}, {1.0});
    const VertexSimplexEnergy<2> energy(inner, {R.inverse()});
    Vec<6> x;
    x << 0.1, 0.2, 1.3, 0.1, 0.4, 1.2;
    Mat<2> P;
    P << x[2] - x[0], x[4] - x[0], x[3] - x[1], x[5] - x[1];
    const Mat<2> A = P * R.inverse();
    EXPECT_NEAR(energy.value(0, x), inner.value(0, Eigen::Map<const Vec<4>>(A.data())), 1e-12);
    EXPECT_TRUE(check_derivatives(energy, 0, x).passes(1e-6));
}

TEST(PolynomialRoots, SmallestPositiveRoot) {
    EXPECT_DOUBLE_EQ(smallest_positive_root(-2.0, 1.0, 0.0), 2.0);            // t - 2
    EXPECT_DOUBLE_EQ(smallest_positive_root(6.0, -5.0, 1.0), 2.0);            // (t-2)(t-3)
    EXPECT_EQ(smallest_positive_root(1.0, 0.0, 1.0), kInfinity);              // t^2 + 1
    EXPECT_NEAR(smallest_positive_root(-6.0, 11.0, -6.0, 1.0), 1.0, 1e-14);   // (t-1)(t-2)(t-3)
    EXPECT_EQ(smallest_positive_root(6.0, 11.0, 6.0, 1.0), kInfinity);        // roots -1, -2, -3
    EXPECT_NEAR(smallest_positive_root(1.0, 0.0, 0.0, -1.0), 1.0, 1e-14);     // 1 - t^3
    EXPECT_NEAR(smallest_positive_root(1.0, -1e8, 0.0, 1e-30), 1e-8, 1e-20);  // tiny cubic term
}

}  // namespace
}  // namespace sa
