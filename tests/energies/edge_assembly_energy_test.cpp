#include <gtest/gtest.h>

#include <random>

#include "energies/edge_assembly_energy.h"
#include "energies/polynomial_roots.h"
#include "optim/derivative_check.h"

namespace sa {
namespace {

TEST(EdgeAssemblyEnergy, DerivativesMatchFiniteDifferences) {
    std::mt19937 rng(3);
    std::normal_distribution<double> normal;
    const EdgeAssemblyEnergy<2> e2({edge_moment<2>({Vec<2>(1.0, 2.0)})});
    const EdgeAssemblyEnergy<3> e3(
        {edge_moment<3>({Vec<3>(1.0, 0.0, 0.0), Vec<3>(0.0, 1.0, 0.5), Vec<3>(-1.0, 1.0, 0.5)})});
    Vec<8> x2;
    Vec<18> x3;
    for (int i = 0; i < 8; ++i) x2[i] = normal(rng);
    for (int i = 0; i < 18; ++i) x3[i] = normal(rng);
    EXPECT_TRUE(check_derivatives(e2, 0, x2).passes(1e-7));
    EXPECT_TRUE(check_derivatives(e3, 0, x3).passes(1e-7));
}

TEST(EdgeAssemblyEnergy, IsZeroExactlyWhenTheSharedEdgesAgree) {
    const Vec<2> edge(3.0, 4.0);
    const EdgeAssemblyEnergy<2> energy({edge_moment<2>({edge})});
    Mat<2> Ai, Aj;
    Ai << 1.0, 2.0, 0.5, 3.0;
    // Aj differs from Ai only in the direction orthogonal to the edge: A e agrees.
    const Vec<2> normal(-4.0, 3.0);
    Aj = Ai + Vec<2>(0.7, -0.2) * normal.transpose();
    Vec<8> x;
    x << Eigen::Map<const Vec<4>>(Ai.data()), Eigen::Map<const Vec<4>>(Aj.data());
    EXPECT_NEAR(energy.value(0, x), 0.0, 1e-14);  // round-off of normalizing e
    // A change along the edge is penalized by |dA e|^2 with e normalized.
    x[4] += 0.1;  // Aj(0,0)
    EXPECT_NEAR(energy.value(0, x), std::pow(0.1 * 3.0 / 5.0, 2), 1e-15);
}

TEST(PolynomialRoots, SmallestPositiveRoot) {
    EXPECT_DOUBLE_EQ(smallest_positive_root(-2.0, 1.0, 0.0), 2.0);          // t - 2
    EXPECT_DOUBLE_EQ(smallest_positive_root(6.0, -5.0, 1.0), 2.0);          // (t-2)(t-3)
    EXPECT_EQ(smallest_positive_root(1.0, 0.0, 1.0), kInfinity);            // t^2 + 1
    EXPECT_NEAR(smallest_positive_root(-6.0, 11.0, -6.0, 1.0), 1.0, 1e-14);  // (t-1)(t-2)(t-3)
    EXPECT_EQ(smallest_positive_root(6.0, 11.0, 6.0, 1.0), kInfinity);  // roots -1, -2, -3
    EXPECT_NEAR(smallest_positive_root(1.0, 0.0, 0.0, -1.0), 1.0, 1e-14);   // 1 - t^3
    EXPECT_NEAR(smallest_positive_root(1.0, -1e8, 0.0, 1e-30), 1e-8, 1e-20);  // tiny cubic term
}

}  // namespace
}  // namespace sa
