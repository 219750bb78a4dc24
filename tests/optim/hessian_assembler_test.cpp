#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "optim/detail/hessian_assembler.h"
#include "optim/optim.h"
#include "test_energies.h"

namespace sa {
namespace {

/// 0.5 * c * (x_i - 2 x_j)^2: quadratic and convex, coupling two variables.
struct QuadraticLink : AutodiffEnergy<QuadraticLink, 2> {
    static constexpr bool is_quadratic = true;
    static constexpr bool is_convex = true;
    template <class T>
    T energy(Index e, const Eigen::Matrix<T, 2, 1>& x) const {
        return 0.5 * (1.0 + 0.1 * double(e % 7)) * (x[0] - 2.0 * x[1]) * (x[0] - 2.0 * x[1]);
    }
};

/// (x_0 x_1 + x_2 x_3)^2 over two blocks of two variables, only its diagonal 2 x 2 blocks
/// assembled (optim/element_energy.h's hessian_block).
struct BlockCoupled : AutodiffEnergy<BlockCoupled, 4> {
    static constexpr int hessian_block = 2;
    template <class T>
    T energy(Index, const Eigen::Matrix<T, 4, 1>& x) const {
        const T s = x[0] * x[1] + x[2] * x[3];
        return s * s;
    }
};

/// 0.5 (sum_k x_k)^2 + sum_k cos(x_k) over any number of variables: a dense Hessian that is not
/// positive semidefinite everywhere (dynamic_element_energy.h).
struct DenseRagged {
    static constexpr int arity = kDynamicArity;
    double value(Index, ConstVectorRef x) const {
        return 0.5 * x.sum() * x.sum() + x.array().cos().sum();
    }
    double value_gradient_hessian(Index e, ConstVectorRef x, VectorRef g, MatrixRef h) const {
        g = Eigen::VectorXd::Constant(x.size(), x.sum()) - x.array().sin().matrix();
        h.setOnes();
        h.diagonal() -= x.array().cos().matrix();
        return value(e, x);
    }
};

/// (sum_p x_2p x_2p+1)^2 over pairs of variables, only its diagonal 2 x 2 blocks assembled: the
/// B x n form of dynamic_element_energy.h.
struct BlockedRagged {
    static constexpr int arity = kDynamicArity;
    static constexpr int hessian_block = 2;
    static double pair_sum(ConstVectorRef x) {
        double s = 0.0;
        for (Index p = 0; 2 * p < x.size(); ++p) s += x[2 * p] * x[2 * p + 1];
        return s;
    }
    double value(Index, ConstVectorRef x) const { return pair_sum(x) * pair_sum(x); }
    double value_gradient_hessian(Index, ConstVectorRef x, VectorRef g, MatrixRef h) const {
        const double s = pair_sum(x);
        for (Index p = 0; 2 * p < x.size(); ++p) {
            const double a = x[2 * p], b = x[2 * p + 1];
            g[2 * p] = 2.0 * s * b;
            g[2 * p + 1] = 2.0 * s * a;
            h.middleCols(2 * p, 2) << 2.0 * b * b, 2.0 * a * b + 2.0 * s, 2.0 * a * b + 2.0 * s,
                2.0 * a * a;
        }
        return s * s;
    }
};

/// The dense sum of every term's weighted, projected element Hessians over all variables, each
/// element's entries outside its Hessian blocks left out.
Eigen::MatrixXd dense_reference(const Problem& problem, const Eigen::VectorXd& x) {
    const Index n = problem.num_variables();
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
    for (TermId t = 0; t < problem.num_terms(); ++t) {
        const Term& term = problem.term(t);
        const TermLayout l = term.layout();
        std::vector<double> g(std::size_t(l.num_entries()));
        std::vector<double> h(std::size_t(l.num_hessian_slots()));
        term.evaluate(x, term.weight(), g.data(), h.data());
        if (!term.is_convex()) term.project(x, h.data(), ProjectionMode::kClamp, 1e-8);
        for (Index e = 0; e < l.num_elements; ++e) {
            const Index* vars = term.element_variables(e);
            const int N = l.arity_of(e), B = l.block_of(e);
            for (int a = 0; a < N; ++a)
                for (int b = 0; b < N; ++b)
                    if (a / B == b / B)
                        H(vars[b], vars[a]) +=
                            h[std::size_t(l.hessian_begin(e) + hessian_slot(B, a, b))];
        }
    }
    return H;
}

/// The largest difference between a and b on and below the diagonal.
double largest_lower_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    double largest = 0.0;
    for (Index j = 0; j < a.cols(); ++j) {
        for (Index i = j; i < a.rows(); ++i)
            largest = std::max(largest, std::abs(a(i, j) - b(i, j)));
    }
    return largest;
}

// The assembled lower triangle equals the dense sum of the element Hessians restricted to the free
// variables, for terms with and without a constant Hessian sharing entries, repeated elements,
// fixed variables and a variable no term uses.
TEST(HessianAssembler, MatchesTheDenseSumOfElementHessians) {
    const int n = 300;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::uniform_int_distribution<int> pick(0, n - 2);  // variable n - 1 is used by no term
    Eigen::VectorXd x0(n);
    for (int i = 0; i < n; ++i) x0[i] = uniform(rng);
    Problem problem(x0);
    std::vector<std::array<Index, 2>> links, springs;
    for (int k = 0; k < 4 * n; ++k) {
        const int a = pick(rng), b = pick(rng);
        if (a != b) links.push_back({a, b});
        const int c = pick(rng), d = pick(rng);
        if (c != d) springs.push_back({c, d});
    }
    links.push_back(links.front());  // the same element twice
    test::Parabola parabola;
    std::vector<std::array<Index, 1>> singles;
    for (int i = 0; i < n - 1; i += 3) {
        parabola.curvature.push_back(2.0);
        parabola.target.push_back(0.5);
        singles.push_back({i});
    }
    problem.add_term("rosenbrock", test::RosenbrockLink{}, springs, 0.3);
    problem.add_term("links", QuadraticLink{}, links, 2.0);
    problem.add_term("parabola", parabola, singles, 0.7);
    problem.add_term("springs", test::Spring{}, links, 1.5);
    for (int i = 0; i < n; i += 11) problem.set_fixed(i);

    HessianAssembler assembler(problem);
    PhaseTimes times;
    assembler.evaluate(problem, problem.variables(), ProjectionMode::kClamp, 1e-8, times);
    const Eigen::MatrixXd reference = dense_reference(problem, problem.variables());
    const Eigen::MatrixXd assembled = Eigen::MatrixXd(assembler.hessian());
    const std::vector<Index>& variable = assembler.variable_of_free();
    ASSERT_EQ(assembler.num_free(), n - 1 - (n - 1 + 10) / 11);
    double largest_error = 0.0;
    for (Index j = 0; j < assembler.num_free(); ++j) {
        for (Index i = 0; i < assembler.num_free(); ++i) {
            const double expected = i >= j ? reference(variable[i], variable[j]) : 0.0;
            largest_error = std::max(largest_error, std::abs(assembled(i, j) - expected));
        }
    }
    EXPECT_LT(largest_error, 1e-9 * reference.cwiseAbs().maxCoeff());
    // Every stored entry is in the lower triangle and the diagonal is stored.
    for (Index j = 0; j < assembler.num_free(); ++j) {
        EXPECT_EQ(assembler.hessian().innerIndexPtr()[assembler.diagonal_positions()[j]], j);
    }
}

// A term with Hessian blocks adds neither values nor pattern entries between its blocks: with
// each element's two blocks on variables no other term links, the matrix stays block diagonal.
TEST(HessianAssembler, KeepsOnlyTheDiagonalBlocksOfABlockedTerm) {
    const int n = 40;
    Eigen::VectorXd x0(n);
    for (int i = 0; i < n; ++i) x0[i] = 0.3 + 0.05 * i;
    Problem problem(x0);
    std::vector<std::array<Index, 4>> elements;
    for (int i = 0; i + 3 < n; i += 4) elements.push_back({i, i + 1, i + 2, i + 3});
    elements.push_back({0, 1, 6, 7});  // block (0, 1) with block (6, 7), coupled again
    problem.add_term("blocks", BlockCoupled{}, elements, 1.5);
    EXPECT_EQ(problem.term(0).layout().block, 2);

    HessianAssembler assembler(problem);
    PhaseTimes times;
    assembler.evaluate(problem, problem.variables(), ProjectionMode::kClamp, 1e-8, times);
    EXPECT_EQ(assembler.hessian().nonZeros(), n / 2 * 3);  // two diagonals and one below each
    const Eigen::MatrixXd reference = dense_reference(problem, problem.variables());
    const Eigen::MatrixXd assembled = Eigen::MatrixXd(assembler.hessian());
    const double largest_error = largest_lower_difference(assembled, reference);
    EXPECT_GT(reference.cwiseAbs().maxCoeff(), 0.1);
    EXPECT_LT(largest_error, 1e-12 * reference.cwiseAbs().maxCoeff());
}

// Terms of run-time arity, elements of 1 to 7 variables (dense) and of 1 to 5 pairs (blocked),
// sharing variables with each other and with a fixed-arity term: assembled as the dense sum.
TEST(HessianAssembler, AssemblesRaggedElementsDenseAndBlocked) {
    const int n = 120;
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::uniform_int_distribution<int> size(1, 7), pairs(1, 5);
    Eigen::VectorXd x0(n);
    for (int i = 0; i < n; ++i) x0[i] = uniform(rng);
    Problem problem(x0);
    std::vector<Index> all(n);
    std::iota(all.begin(), all.end(), Index(0));
    // `count` distinct variables at random.
    const auto some = [&](int count) {
        std::shuffle(all.begin(), all.end(), rng);
        return std::vector<Index>(all.begin(), all.begin() + count);
    };
    RaggedElements dense, blocked;
    std::vector<std::array<Index, 2>> links;
    for (int k = 0; k < 60; ++k) {
        dense.push_back(some(size(rng)));
        blocked.push_back(some(2 * pairs(rng)));
        const std::vector<Index> link = some(2);
        links.push_back({link[0], link[1]});
    }
    problem.add_term("dense", DenseRagged{}, std::move(dense), 0.8);
    problem.add_term("blocked", BlockedRagged{}, std::move(blocked), 1.3);
    problem.add_term("links", QuadraticLink{}, links, 2.0);
    EXPECT_EQ(problem.term(1).layout().block, 2);

    HessianAssembler assembler(problem);
    PhaseTimes times;
    assembler.evaluate(problem, problem.variables(), ProjectionMode::kClamp, 1e-8, times);
    const Eigen::MatrixXd reference = dense_reference(problem, problem.variables());
    const Eigen::MatrixXd assembled = Eigen::MatrixXd(assembler.hessian());
    ASSERT_EQ(assembler.num_free(), n);
    const double largest_error = largest_lower_difference(assembled, reference);
    EXPECT_GT(reference.cwiseAbs().maxCoeff(), 0.1);
    EXPECT_LT(largest_error, 1e-12 * reference.cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace sa
