#include "energies/linear_constraint_energy.h"

#include <gtest/gtest.h>

#include <random>

#include "optim/derivative_check.h"

namespace sa {
namespace {

TEST(LinearConstraintEnergy, IsTheSquaredResidualWithItsDerivatives) {
    std::mt19937 random(3);
    std::normal_distribution<double> normal;
    LinearConstraintRows<5, 2> rows;
    for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 5; ++j) rows.coefficients(i, j) = normal(random);
        rows.rhs[i] = normal(random);
    }
    const LinearConstraintEnergy<5, 2> energy({rows});
    Vec<5> x;
    for (int j = 0; j < 5; ++j) x[j] = normal(random);
    EXPECT_NEAR(energy.value(0, x), (rows.coefficients * x - rows.rhs).squaredNorm(), 1e-14);
    EXPECT_TRUE(check_derivatives(energy, 0, x).passes(1e-7));
    Vec<5> g;
    Mat<5> h;
    energy.value_gradient_hessian(0, x, g, h);
    EXPECT_TRUE(h.isApprox(2.0 * rows.coefficients.transpose() * rows.coefficients));
    static_assert(LinearConstraintEnergy<5, 2>::is_quadratic &&
                  LinearConstraintEnergy<5, 2>::is_convex);
    LinearConstraintRows<5, 2> bad = rows;
    bad.rhs[1] = std::nan("");
    EXPECT_THROW((LinearConstraintEnergy<5, 2>({rows, bad})), InvalidArgumentError);
}

}  // namespace
}  // namespace sa
