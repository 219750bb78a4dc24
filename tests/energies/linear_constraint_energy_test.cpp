#include "energies/linear_constraint_energy.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "energies/reindexed_energy.h"
#include "energies/simplex_energy.h"
#include "optim/derivative_check.h"

namespace sa {
namespace {

TEST(LinearConstraintEnergy, IsTheSquaredResidualWithExactDerivatives) {
    std::mt19937 rng(6);
    std::normal_distribution<double> n;
    Eigen::Matrix<double, 2, 5> C;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 5; ++j) C(i, j) = n(rng);
    const Vec<2> b(0.3, -1.0);
    const LinearConstraintEnergy<2, 5> energy({C}, {b});
    Vec<5> x;
    for (int j = 0; j < 5; ++j) x[j] = n(rng);
    EXPECT_NEAR(energy.value(0, x), (C * x - b).squaredNorm(), 1e-14);
    EXPECT_TRUE(check_derivatives(energy, 0, x).passes(1e-7));
    Vec<5> g;
    Mat<5> h;
    energy.value_gradient_hessian(0, x, g, h);
    EXPECT_LT((h - 2.0 * C.transpose() * C).norm(), 1e-14);
    static_assert(is_quadratic_energy<LinearConstraintEnergy<2, 5>>());
    static_assert(is_convex_energy<LinearConstraintEnergy<2, 5>>());
}

TEST(ReindexedEnergy, EvaluatesTheSelectedElementsAndForwardsWhatTheInnerHas) {
    const auto inner = std::make_shared<const SimplexEnergy<2>>(SimplexEnergyOptions{},
                                                                std::vector<double>{1.0, 2.0, 3.0});
    const ReindexedEnergy<SimplexEnergy<2>> picked(inner, {2, 0});
    const Vec<4> a(1.2, 0.1, -0.2, 0.9), da(-1.0, 0.0, 0.0, -1.0);
    EXPECT_EQ(picked.value(0, a), inner->value(2, a));
    EXPECT_EQ(picked.max_step(1, a, da), inner->max_step(0, a, da));
    static_assert(HasMaxStep<ReindexedEnergy<SimplexEnergy<2>>>);
    static_assert(HasOwnProjection<ReindexedEnergy<SimplexEnergy<2>>>);
    static_assert(!HasMaxStep<ReindexedEnergy<LinearConstraintEnergy<1, 2>>>);
    static_assert(is_quadratic_energy<ReindexedEnergy<LinearConstraintEnergy<1, 2>>>());
}

}  // namespace
}  // namespace sa
