#include <gtest/gtest.h>

#include <random>

#include "optim/optim.h"
#include "test_energies.h"

namespace sa {
namespace {

using test::DoubleWell;
using test::LogBarrier;
using test::LogBarrierWithoutMaxStep;
using test::Parabola;
using test::RosenbrockLink;
using test::Spring;

// A convex quadratic: parabolas pulling each variable to a target, springs along a chain.
template <class SpringEnergy>
Problem make_convex_quadratic(int n, SpringEnergy spring) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uniform(0.5, 2.0);
    Parabola parabola;
    std::vector<std::array<Index, 1>> singles;
    std::vector<std::array<Index, 2>> links;
    for (int i = 0; i < n; ++i) {
        parabola.curvature.push_back(uniform(rng));
        parabola.target.push_back(uniform(rng) * 10.0);
        singles.push_back({i});
        if (i + 1 < n) links.push_back({i, i + 1});
    }
    Problem problem(Eigen::VectorXd::Zero(n));
    problem.add_term("parabola", parabola, singles);
    problem.add_term("spring", spring, links, 3.0);
    return problem;
}

struct QuadraticSpring : Spring {
    static constexpr bool is_quadratic = true;
};

TEST(NewtonSolver, ConvexQuadraticIsSolvedInOneStep) {
    Problem problem = make_convex_quadratic(50, Spring{});
    NewtonOptions options;
    options.projection = ProjectionMode::kNone;  // convex: nothing to project
    const NewtonSummary summary = solve(problem, options);
    EXPECT_TRUE(summary.success()) << summary.message;
    EXPECT_EQ(summary.num_steps(), 1);
    EXPECT_EQ(summary.iterations[1].step_length, 1.0);
    EXPECT_LT(summary.final_gradient_norm, 1e-10);
}

TEST(NewtonSolver, QuadraticTermsAreAssembledOnceAndStillExact) {
    Problem problem = make_convex_quadratic(50, QuadraticSpring{});
    const NewtonSummary summary = solve(problem);  // default projection: clamp
    EXPECT_TRUE(summary.success()) << summary.message;
    EXPECT_EQ(summary.num_steps(), 1);
    // Same minimizer as the non-quadratic formulation.
    Problem reference = make_convex_quadratic(50, Spring{});
    NewtonOptions options;
    options.projection = ProjectionMode::kNone;
    solve(reference, options);
    EXPECT_LT((problem.variables() - reference.variables()).lpNorm<Eigen::Infinity>(), 1e-12);
}

TEST(NewtonSolver, RosenbrockChainConverges) {
    const int n = 10;
    Eigen::VectorXd x0(n);
    for (int i = 0; i < n; ++i) x0[i] = i % 2 == 0 ? -1.2 : 1.0;
    Problem problem(x0);
    std::vector<std::array<Index, 2>> links;
    for (int i = 0; i + 1 < n; ++i) links.push_back({i, i + 1});
    problem.add_term("rosenbrock", RosenbrockLink{}, links);
    const NewtonSummary summary = solve(problem);
    ASSERT_TRUE(summary.success()) << summary.full_report();
    EXPECT_LT(summary.final_gradient_norm, 1e-6);
    // Every accepted step decreased the energy.
    for (std::size_t k = 1; k < summary.iterations.size(); ++k) {
        EXPECT_GT(summary.iterations[k].energy_change, 0.0);
    }
    // The projection had work to do: the problem is not convex along the way.
    Index projected = 0;
    for (std::size_t k = 1; k < summary.iterations.size(); ++k) {
        projected += summary.iterations[k].projected_blocks;
    }
    EXPECT_GT(projected, 0);
}

TEST(NewtonSolver, RosenbrockPairReachesTheGlobalMinimum) {
    Problem problem(Eigen::Vector2d(-1.2, 1.0));
    problem.add_term("rosenbrock", RosenbrockLink{}, {{0, 1}});
    const NewtonSummary summary = solve(problem);
    ASSERT_TRUE(summary.success()) << summary.full_report();
    EXPECT_NEAR(problem.variables()[0], 1.0, 1e-8);
    EXPECT_NEAR(problem.variables()[1], 1.0, 1e-8);
}

// c x - log x from x = 10: the full Newton step lands at x < 0.
template <class Barrier>
Problem make_barrier_problem(int n, std::atomic<int>* infeasible) {
    Barrier barrier;
    barrier.infeasible_evaluations = infeasible;
    Problem problem(Eigen::VectorXd::Constant(n, 10.0));
    std::vector<std::array<Index, 1>> singles;
    for (int i = 0; i < n; ++i) singles.push_back({i});
    problem.add_term("barrier", barrier, singles);
    return problem;
}

TEST(NewtonSolver, BarrierProblemNeverEvaluatesAnInfeasiblePoint) {
    std::atomic<int> infeasible{0};
    Problem problem = make_barrier_problem<LogBarrier>(100, &infeasible);
    const NewtonSummary summary = solve(problem);
    ASSERT_TRUE(summary.success()) << summary.full_report();
    EXPECT_EQ(infeasible.load(), 0);
    EXPECT_LT((problem.variables().array() - 1.0).abs().maxCoeff(), 1e-6);
    EXPECT_LT(summary.iterations[1].max_feasible_step, 1.0);  // the first step was capped
}

TEST(NewtonSolver, ExpandingLineSearchStaysFeasible) {
    std::atomic<int> infeasible{0};
    Problem problem = make_barrier_problem<LogBarrier>(100, &infeasible);
    NewtonOptions options;
    options.line_search.expand = true;
    const NewtonSummary summary = solve(problem, options);
    ASSERT_TRUE(summary.success()) << summary.full_report();
    EXPECT_EQ(infeasible.load(), 0);
    EXPECT_LT((problem.variables().array() - 1.0).abs().maxCoeff(), 1e-6);
}

// exp((x - c)^2) from x = c + 3: the full Newton step, -u / (1 + 2 u^2) for u = x - c, is a small
// part of the way, and Newton alone crawls; doubling the step while the energy falls does not.
TEST(NewtonSolver, ExpandingLineSearchTakesLongerStepsWhereTheModelIsTooCurved) {
    const int n = 20;
    auto solve_from_far = [&](bool expand) {
        Problem problem(Eigen::VectorXd::LinSpaced(n, 3.0, 4.0));
        std::vector<std::array<Index, 1>> singles;
        for (int i = 0; i < n; ++i) singles.push_back({i});
        problem.add_elements<1>("exp", singles, [](const auto& x, Index e) {
            using std::exp;
            const auto u = x[0] - 0.1 * static_cast<double>(e);
            return exp(u * u);
        });
        NewtonOptions options;
        options.line_search.expand = expand;
        options.gradient_tolerance = 1e-9;
        const NewtonSummary summary = solve(problem, options);
        EXPECT_TRUE(summary.success()) << summary.full_report();
        for (int i = 0; i < n; ++i) EXPECT_NEAR(problem.variables()[i], 0.1 * i, 1e-6);
        return summary.num_steps();
    };
    const int plain = solve_from_far(false), expanded = solve_from_far(true);
    EXPECT_LT(2 * expanded, plain) << "plain " << plain << ", expanded " << expanded;
}

TEST(NewtonSolver, InfiniteTrialValuesAreRejectedWithoutMaxStep) {
    std::atomic<int> infeasible{0};
    Problem problem = make_barrier_problem<LogBarrierWithoutMaxStep>(100, &infeasible);
    const NewtonSummary summary = solve(problem);
    ASSERT_TRUE(summary.success()) << summary.full_report();
    EXPECT_GT(infeasible.load(), 0);  // it had to try, and backtracked
    EXPECT_LT((problem.variables().array() - 1.0).abs().maxCoeff(), 1e-6);
}

TEST(NewtonSolver, InfeasibleStartIsReported) {
    std::atomic<int> infeasible{0};
    Problem problem = make_barrier_problem<LogBarrier>(3, &infeasible);
    Eigen::VectorXd x = problem.variables();
    x[1] = -1.0;
    problem.set_variables(x);
    const NewtonSummary summary = solve(problem);
    EXPECT_EQ(summary.termination, TerminationType::kInfeasibleStart);
    EXPECT_FALSE(summary.success());
    EXPECT_EQ(problem.variables(), x);
}

TEST(NewtonSolver, IndefiniteMatrixTriggersRegularizationAndStillConverges) {
    const int n = 10;
    DoubleWell well;
    well.tilt = 0.1;
    std::vector<std::array<Index, 1>> singles;
    for (int i = 0; i < n; ++i) singles.push_back({i});
    Problem problem(Eigen::VectorXd::Constant(n, 0.1));  // between the wells: f'' < 0
    problem.add_term("double well", well, singles);
    NewtonOptions options;
    options.projection = ProjectionMode::kNone;  // leave the indefinite Hessian to the solver
    const NewtonSummary summary = solve(problem, options);
    ASSERT_TRUE(summary.success()) << summary.full_report();
    EXPECT_GT(summary.iterations[1].regularization, 0.0);
    EXPECT_GT(summary.iterations[1].factorizations, 1);
    for (int i = 0; i < n; ++i) {  // a minimum: f' = x^3 - x + 0.1 = 0 and f'' > 0
        const double x = problem.variables()[i];
        EXPECT_NEAR(x * x * x - x + 0.1, 0.0, 1e-6);
        EXPECT_GT(3 * x * x - 1, 0.0);
    }
}

TEST(NewtonSolver, RegularizationOnlyTouchesBlocksThatAllowIt) {
    DoubleWell well;
    Problem problem(Eigen::Vector2d(0.1, 0.1));
    problem.add_term("double well", well, {{0}, {1}});
    problem.set_regularize_on_failure(problem.add_variable_block("second", 1, 2), false);
    NewtonOptions options;
    options.projection = ProjectionMode::kNone;
    const NewtonSummary summary = solve(problem, options);
    // Variable 1's negative curvature can never be regularized away.
    EXPECT_EQ(summary.termination, TerminationType::kFactorizationFailed);
    EXPECT_FALSE(summary.success());
}

TEST(NewtonSolver, FixedVariablesKeepTheirValues) {
    Problem problem = make_convex_quadratic(20, Spring{});
    Eigen::VectorXd x = problem.variables();
    x[3] = 42.0;
    problem.set_variables(x);
    problem.set_fixed(3);
    const NewtonSummary summary = solve(problem);
    ASSERT_TRUE(summary.success()) << summary.message;
    EXPECT_EQ(problem.variables()[3], 42.0);
    EXPECT_EQ(summary.num_free_variables, 19);
}

TEST(NewtonSolver, CallbacksSeeEveryIterationAndCanStopIt) {
    Problem problem(Eigen::Vector2d(-1.2, 1.0));
    problem.add_term("rosenbrock", RosenbrockLink{}, {{0, 1}});
    std::vector<int> seen;
    NewtonOptions options;
    options.callbacks.push_back([&](const IterationContext& context) {
        seen.push_back(context.record.iteration);
        EXPECT_EQ(context.term_values.size(), 1u);
        EXPECT_DOUBLE_EQ(context.term_values[0], context.record.energy);
        return context.record.iteration == 3 ? CallbackResult::kStopSuccess
                                             : CallbackResult::kContinue;
    });
    const NewtonSummary summary = solve(problem, options);
    EXPECT_EQ(summary.termination, TerminationType::kUserSuccess);
    EXPECT_EQ(seen, (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(summary.num_steps(), 3);
}

// A callback that takes the start ends the solve before the Hessian's pattern and its symbolic
// factorization are made; a later solve with the same solver makes them and converges.
TEST(NewtonSolver, AStartTakenAtIterationZeroIsNotAnalyzed) {
    Problem problem = make_convex_quadratic(10, Spring{});
    bool take_start = true;
    NewtonOptions options;
    options.callbacks.push_back([&](const IterationContext&) {
        return take_start ? CallbackResult::kStopSuccess : CallbackResult::kContinue;
    });
    NewtonSolver solver(options);
    const NewtonSummary taken = solver.solve(problem);
    EXPECT_EQ(taken.termination, TerminationType::kUserSuccess);
    EXPECT_EQ(taken.num_steps(), 0);
    EXPECT_EQ(taken.num_free_variables, 0);
    EXPECT_EQ(taken.hessian_nonzeros, 0);
    EXPECT_EQ(taken.times.analyze, 0.0);
    take_start = false;
    const NewtonSummary solved = solver.solve(problem);
    ASSERT_TRUE(solved.success()) << solved.message;
    EXPECT_EQ(solved.num_free_variables, 10);
    EXPECT_GT(solved.hessian_nonzeros, 0);
    EXPECT_GT(solved.num_steps(), 0);
}

TEST(NewtonSolver, CallbacksMayChangeWeightsBetweenIterations) {
    Problem problem = make_convex_quadratic(10, Spring{});
    NewtonOptions options;
    options.projection = ProjectionMode::kNone;
    options.callbacks.push_back([](const IterationContext& context) {
        if (context.record.iteration <= 2)
            context.problem.set_weight(1, 10.0 * (context.record.iteration + 1));
        return CallbackResult::kContinue;
    });
    const NewtonSummary summary = solve(problem, options);
    ASSERT_TRUE(summary.success()) << summary.message;
    EXPECT_GE(summary.num_steps(), 3);  // each weight change moves the minimizer
    EXPECT_EQ(problem.weight(1), 30.0);
}

TEST(NewtonSolver, IterationLimitIsReported) {
    Problem problem(Eigen::Vector2d(-1.2, 1.0));
    problem.add_term("rosenbrock", RosenbrockLink{}, {{0, 1}});
    NewtonOptions options;
    options.max_iterations = 2;
    const NewtonSummary summary = solve(problem, options);
    EXPECT_EQ(summary.termination, TerminationType::kMaxIterations);
    EXPECT_EQ(summary.num_steps(), 2);
    EXPECT_FALSE(summary.success());
}

// The limit is checked before the Hessian's setup (its pattern and symbolic analysis, as long as
// an iteration on a large system) and before the first iteration: a solve whose time is up stops
// there instead of running one more, possibly long, step.
TEST(NewtonSolver, TimeLimitPassedBeforeTheSetupSkipsIt) {
    Problem problem(Eigen::Vector2d(-1.2, 1.0));
    problem.add_term("rosenbrock", RosenbrockLink{}, {{0, 1}});
    NewtonOptions options;
    options.max_time_seconds = 1e-12;
    const NewtonSummary summary = solve(problem, options);
    EXPECT_EQ(summary.termination, TerminationType::kMaxTime);
    EXPECT_EQ(summary.num_steps(), 0);
    EXPECT_EQ(problem.variables(), Eigen::Vector2d(-1.2, 1.0));
    EXPECT_NE(summary.message.find("before the Hessian's setup"), std::string::npos)
        << summary.message;
    EXPECT_EQ(summary.times.setup, 0.0);
    EXPECT_EQ(summary.times.analyze, 0.0);
}

TEST(NewtonSolver, ReportsNameTheOutcome) {
    Problem problem = make_convex_quadratic(10, Spring{});
    const NewtonSummary summary = solve(problem);
    EXPECT_NE(summary.brief_report().find("converged"), std::string::npos);
    EXPECT_NE(summary.full_report().find("factorize"), std::string::npos);
    std::ostringstream progress;
    NewtonOptions options;
    options.callbacks.push_back(ProgressPrinter(progress));
    Problem again = make_convex_quadratic(10, Spring{});
    const NewtonSummary printed = solve(again, options);
    EXPECT_NE(progress.str().find("energy"), std::string::npos);
    // A header, then a row for the start and one per step.
    const std::string text = progress.str();
    const auto lines = std::count(text.begin(), text.end(), '\n');
    EXPECT_EQ(lines, 2 + printed.num_steps());
}

TEST(NewtonSolver, ExceptionInAnElementReachesTheCallerAndTheProblemStaysUsable) {
    std::atomic<bool> armed{false};
    test::ThrowingSpring spring;
    spring.armed = &armed;
    Problem problem = make_convex_quadratic(30, spring);
    NewtonSolver solver;
    solver.options().projection = ProjectionMode::kNone;
    Eigen::VectorXd last_seen;
    solver.options().callbacks.push_back([&](const IterationContext& context) {
        last_seen = context.problem.variables();
        armed = true;  // the next evaluation throws
        return CallbackResult::kContinue;
    });
    EXPECT_THROW(solver.solve(problem), std::runtime_error);
    EXPECT_EQ(problem.variables(), last_seen);  // the last accepted iterate, intact
    armed = false;
    solver.options().callbacks.clear();
    const NewtonSummary summary = solver.solve(problem);
    EXPECT_TRUE(summary.success()) << summary.message;
}

TEST(NewtonSolver, SecondSolveReusesTheSetup) {
    Problem problem = make_convex_quadratic(200, Spring{});
    NewtonSolver solver;
    const NewtonSummary first = solver.solve(problem);
    const NewtonSummary second = solver.solve(problem);
    EXPECT_TRUE(first.success());
    EXPECT_TRUE(second.success());
    EXPECT_EQ(second.times.setup, 0.0);
    EXPECT_EQ(second.times.analyze, 0.0);
    problem.set_fixed(0);  // a new structure: set up again
    const NewtonSummary third = solver.solve(problem);
    EXPECT_GT(third.times.setup, 0.0);
}

}  // namespace
}  // namespace sa
