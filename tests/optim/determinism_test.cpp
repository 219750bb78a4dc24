#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <random>

#include "optim/detail/hessian_assembler.h"
#include "optim/optim.h"
#include "test_energies.h"

namespace sa {
namespace {

// Enough elements, and enough elements sharing variables, for the parallel loops to split and
// for many matrix entries to sum several contributions.
Problem make_problem() {
    const int n = 20000;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::uniform_int_distribution<int> offset(1, 40);  // local pairs keep the factor sparse
    Eigen::VectorXd x0(n);
    for (int i = 0; i < n; ++i) x0[i] = uniform(rng);
    Problem problem(x0);
    std::vector<std::array<Index, 2>> chain, random_pairs;
    for (int i = 0; i + 1 < n; ++i) chain.push_back({i, i + 1});
    for (int k = 0; k < 3 * n; ++k) {
        const int a = k % n, b = (a + offset(rng)) % n;
        random_pairs.push_back({a, b});
    }
    test::Parabola parabola;
    std::vector<std::array<Index, 1>> singles;
    for (int i = 0; i < n; ++i) {
        parabola.curvature.push_back(1.0 + uniform(rng) * 0.5);
        parabola.target.push_back(uniform(rng));
        singles.push_back({i});
    }
    problem.add_term("rosenbrock", test::RosenbrockLink{}, chain, 0.01);
    problem.add_term("springs", test::Spring{}, random_pairs, 0.1);
    problem.add_term("parabola", parabola, singles);
    return problem;
}

TEST(Determinism, AssemblyIsBitIdenticalForOneAndTwoThreads) {
    Problem problem = make_problem();
    auto assemble = [&](int threads, Eigen::VectorXd& gradient, std::vector<double>& values) {
        tbb::task_arena arena(threads);
        arena.execute([&] {
            HessianAssembler assembler(problem);
            PhaseTimes times;
            const auto eval = assembler.evaluate(problem, problem.variables(),
                                                 ProjectionMode::kClamp, 1e-8, times);
            EXPECT_TRUE(std::isfinite(eval.energy));
            gradient = assembler.gradient();
            const auto& H = assembler.hessian();
            values.assign(H.valuePtr(), H.valuePtr() + H.nonZeros());
        });
    };
    Eigen::VectorXd g1, g2;
    std::vector<double> h1, h2;
    assemble(1, g1, h1);
    assemble(2, g2, h2);
    ASSERT_EQ(g1.size(), g2.size());
    EXPECT_EQ(std::memcmp(g1.data(), g2.data(), sizeof(double) * g1.size()), 0);
    ASSERT_EQ(h1.size(), h2.size());
    EXPECT_EQ(std::memcmp(h1.data(), h2.data(), sizeof(double) * h1.size()), 0);
}

TEST(Determinism, SolveIsBitIdenticalForOneAndTwoThreads) {
    auto run = [](int threads) {
        Problem problem = make_problem();
        NewtonOptions options;
        options.num_threads = threads;
        const NewtonSummary summary = solve(problem, options);
        EXPECT_TRUE(summary.success()) << summary.message;
        EXPECT_EQ(summary.num_threads, threads);
        return std::make_pair(summary, Eigen::VectorXd(problem.variables()));
    };
    const auto [s1, x1] = run(1);
    const auto [s2, x2] = run(2);
    ASSERT_EQ(s1.num_steps(), s2.num_steps());
    for (std::size_t k = 0; k < s1.iterations.size(); ++k) {
        EXPECT_EQ(s1.iterations[k].energy, s2.iterations[k].energy) << "iteration " << k;
    }
    EXPECT_EQ(std::memcmp(x1.data(), x2.data(), sizeof(double) * x1.size()), 0);
}

}  // namespace
}  // namespace sa
