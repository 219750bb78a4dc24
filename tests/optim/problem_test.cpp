#include <gtest/gtest.h>

#include "optim/optim.h"
#include "test_energies.h"

namespace sa {
namespace {

TEST(Problem, ElementIndexOutOfRangeNamesTermAndElement) {
    Problem problem(Eigen::VectorXd::Zero(3));
    try {
        problem.add_term("springs", test::Spring{}, {{0, 1}, {1, 3}});
        FAIL() << "expected InvalidArgumentError";
    } catch (const InvalidArgumentError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("'springs'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("element 1"), std::string::npos) << msg;
        EXPECT_NE(msg.find("variable 3"), std::string::npos) << msg;
    }
    EXPECT_EQ(problem.num_terms(), 0);
}

TEST(Problem, BadWeightsAndBlocksAreRejected) {
    Problem problem(Eigen::VectorXd::Zero(4));
    EXPECT_THROW(problem.add_term("s", test::Spring{}, {{0, 1}}, -1.0), InvalidArgumentError);
    const TermId t = problem.add_term("s", test::Spring{}, {{0, 1}});
    EXPECT_THROW(problem.set_weight(t, std::nan("")), InvalidArgumentError);
    EXPECT_THROW(problem.set_fixed(4), InvalidArgumentError);
    EXPECT_THROW(problem.add_variable_block("empty", 2, 2), InvalidArgumentError);
    problem.add_variable_block("a", 0, 2);
    EXPECT_THROW(problem.add_variable_block("b", 1, 3), InvalidArgumentError);
    EXPECT_THROW(problem.set_variables(Eigen::VectorXd::Zero(3)), InvalidArgumentError);
}

TEST(Problem, ValueIsTheWeightedSumAndReportsEachTerm) {
    Problem problem(Eigen::Vector3d(0.0, 1.0, 3.0));
    problem.add_term("a", test::Spring{}, {{0, 1}}, 2.0);   // 0.5 * 1
    problem.add_term("b", test::Spring{}, {{1, 2}}, 10.0);  // 0.5 * 4
    std::vector<double> terms;
    EXPECT_DOUBLE_EQ(problem.value(problem.variables(), &terms), 2.0 * 0.5 + 10.0 * 2.0);
    EXPECT_EQ(terms, (std::vector<double>{0.5, 2.0}));
}

TEST(Problem, HessianShiftChangesStepsButNotTheEnergy) {
    auto make = [] {
        Problem problem(Eigen::Vector2d(-1.2, 1.0));
        problem.add_term("rosenbrock", test::RosenbrockLink{}, {{0, 1}});
        return problem;
    };
    Problem plain = make(), shifted = make();
    shifted.set_hessian_shift(shifted.add_variable_block("all", 0, 2), 1.0);
    EXPECT_EQ(plain.value(), shifted.value());
    const NewtonSummary a = solve(plain), b = solve(shifted);
    EXPECT_TRUE(a.success());
    EXPECT_TRUE(b.success());
    EXPECT_NE(a.num_steps(), b.num_steps());
    EXPECT_NEAR(shifted.variables()[0], 1.0, 1e-6);
}

TEST(Problem, VariablesNoTermUsesAreLeftAlone) {
    Problem problem(Eigen::Vector3d(5.0, 0.0, 2.0));
    problem.add_term("s", test::Spring{}, {{0, 2}});
    const NewtonSummary summary = solve(problem);
    EXPECT_TRUE(summary.success());
    EXPECT_EQ(summary.num_free_variables, 2);
    EXPECT_EQ(problem.variables()[1], 0.0);
    EXPECT_NEAR(problem.variables()[0], problem.variables()[2], 1e-6);
}

}  // namespace
}  // namespace sa
