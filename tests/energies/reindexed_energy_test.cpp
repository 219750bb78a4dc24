#include "energies/reindexed_energy.h"

#include <gtest/gtest.h>

#include <memory>

#include "energies/linear_constraint_energy.h"
#include "energies/simplex_energy.h"

namespace sa {
namespace {

TEST(ReindexedEnergy, EvaluatesTheSelectedElementsAndForwardsWhatTheInnerHas) {
    const auto inner = std::make_shared<const SimplexEnergy<2>>(SimplexEnergyOptions{},
                                                                std::vector<double>{1.0, 2.0, 3.0});
    const ReindexedEnergy<SimplexEnergy<2>> picked(inner, {2, 0});
    const Vec<4> a(1.2, 0.1, -0.2, 0.9), da(-1.0, 0.0, 0.0, -1.0);
    EXPECT_EQ(picked.value(0, a), inner->value(2, a));
    EXPECT_EQ(picked.max_step(1, a, da), inner->max_step(0, a, da));
    static_assert(HasMaxStep<ReindexedEnergy<SimplexEnergy<2>>>);
    static_assert(HasOwnProjection<ReindexedEnergy<SimplexEnergy<2>>>);
    static_assert(!HasMaxStep<ReindexedEnergy<LinearConstraintEnergy<2, 1>>>);
    static_assert(is_quadratic_energy<ReindexedEnergy<LinearConstraintEnergy<2, 1>>>());
}

}  // namespace
}  // namespace sa
