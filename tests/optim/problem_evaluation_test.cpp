#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include "optim/optim.h"

namespace sa {
namespace {

// A chain of Rosenbrock links written as a lambda (non-convex), with one variable fixed and one
// that no term uses.
Problem rosenbrock_chain(int n) {
    Eigen::VectorXd x0(n + 1);
    for (int i = 0; i < n; ++i) x0[i] = i % 2 == 0 ? -1.2 : 1.0;
    x0[n] = 42.0;  // unused
    Problem problem(x0);
    std::vector<std::array<Index, 2>> links;
    for (int i = 0; i + 1 < n; ++i) links.push_back({i, i + 1});
    problem.add_elements<2>("rosenbrock", links, [](auto const& x, Index) {
        const auto a = x[1] - x[0] * x[0], b = 1.0 - x[0];
        return 100.0 * a * a + b * b;
    });
    return problem;
}

TEST(ProblemEvaluation, GradientAndHessianMatchFiniteDifferencesOverTheFreeVariables) {
    Problem problem = rosenbrock_chain(6);
    problem.set_fixed(2);
    ProblemEvaluator evaluator(problem, ProjectionMode::kNone);
    const std::vector<Index> free = evaluator.free_variables();
    EXPECT_EQ(free, (std::vector<Index>{0, 1, 3, 4, 5}));
    const Eigen::VectorXd x = problem.variables();
    const ProblemEvaluation e = evaluator.evaluate(x);
    EXPECT_DOUBLE_EQ(e.value, problem.value(x));
    ASSERT_EQ(e.gradient.size(), 5);
    ASSERT_EQ(e.hessian.rows(), 5);
    const Eigen::MatrixXd H = e.hessian;
    EXPECT_LT((H - H.transpose()).cwiseAbs().maxCoeff(), 1e-12);
    const double h = 1e-6;
    for (std::size_t i = 0; i < free.size(); ++i) {
        Eigen::VectorXd xp = x, xm = x;
        xp[free[i]] += h;
        xm[free[i]] -= h;
        EXPECT_NEAR(e.gradient[i], (problem.value(xp) - problem.value(xm)) / (2 * h),
                    1e-6 * std::max(1.0, std::abs(e.gradient[i])));
        const Eigen::VectorXd column =
            (evaluator.evaluate(xp).gradient - evaluator.evaluate(xm).gradient) / (2 * h);
        EXPECT_LT((H.col(i) - column).cwiseAbs().maxCoeff(), 1e-5 * std::max(1.0, H.norm()));
    }
}

TEST(ProblemEvaluation, TheProjectedHessianIsPositiveDefinite) {
    Problem problem = rosenbrock_chain(8);
    // Where 1200 x_i^2 - 400 x_{i+1} + 2 < 0, the links' curvature is negative.
    Eigen::VectorXd x = problem.variables();
    for (int i = 0; i < 8; ++i) x[i] = i % 2 == 0 ? 0.5 : 1.0;
    const Eigen::MatrixXd raw = evaluate(problem, x, ProjectionMode::kNone).hessian;
    const Eigen::MatrixXd projected = evaluate(problem, x, ProjectionMode::kClamp, 1e-6).hessian;
    EXPECT_LT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(raw).eigenvalues()(0), 0.0);
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(projected).eigenvalues()(0), 0.0);
}

TEST(ProblemEvaluation, AUsersOwnNewtonLoopReachesTheMinimum) {
    Problem problem = rosenbrock_chain(6);
    problem.set_fixed(0);
    ProblemEvaluator evaluator(problem);
    Eigen::VectorXd x = problem.variables();
    for (int iteration = 0; iteration < 100; ++iteration) {
        const ProblemEvaluation e = evaluator.evaluate(x);
        if (e.gradient.lpNorm<Eigen::Infinity>() < 1e-10) break;
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(e.hessian);
        ASSERT_EQ(ldlt.info(), Eigen::Success);
        const Eigen::VectorXd step = evaluator.expand(ldlt.solve(-e.gradient));
        EXPECT_EQ(step[0], 0.0);  // fixed
        EXPECT_EQ(step[6], 0.0);  // unused
        double alpha = 1.0;
        while (evaluator.value(x + alpha * step) > e.value) alpha *= 0.5;
        x += alpha * step;
    }
    // x0 = -1.2 is fixed; each following x_{i+1} minimizes its links given the chain.
    Problem reference = rosenbrock_chain(6);
    reference.set_fixed(0);
    ASSERT_TRUE(solve(reference).success());
    EXPECT_LT((x - reference.variables()).norm(), 1e-8);
}

TEST(ProblemEvaluation, InfeasibleAndBadInput) {
    Problem problem(Eigen::Vector2d(1.0, 2.0));
    problem.add_elements<1>("log barrier", {{0}, {1}}, [](auto const& x, Index) {
        using T = ScalarOf<decltype(x)>;
        using std::log;
        if (x[0] <= 0.0) return T(kInfinity);
        return T(x[0] - log(x[0]));
    });
    ProblemEvaluator evaluator(problem);
    const ProblemEvaluation e = evaluator.evaluate(Eigen::Vector2d(1.0, -1.0));
    EXPECT_EQ(e.value, kInfinity);
    EXPECT_EQ(e.gradient.size(), 0);
    EXPECT_THROW(evaluator.evaluate(Eigen::Vector3d::Zero()), InvalidArgumentError);
    EXPECT_THROW(evaluator.expand(Eigen::Vector3d::Zero()), InvalidArgumentError);
    EXPECT_THROW(ProblemEvaluator(problem, ProjectionMode::kClamp, -1.0), InvalidArgumentError);
    // A structure change (a variable fixed) is picked up.
    problem.set_fixed(1);
    EXPECT_EQ(evaluator.evaluate(problem.variables()).gradient.size(), 1);
}

}  // namespace
}  // namespace sa
