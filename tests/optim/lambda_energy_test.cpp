#include <gtest/gtest.h>

#include <cmath>

#include "optim/optim.h"

namespace sa {
namespace {

// A triangle's symmetric Dirichlet energy over its vertex positions (x0 y0 x1 y1 x2 y2), with
// per-element rest data, written once over the scalar type: the shape of a user's lambda.
struct TriangleData {
    std::vector<Eigen::Matrix2d> rest_inverse;
    std::vector<double> area;
};

auto symmetric_dirichlet(const TriangleData& data) {
    return [&data](auto const& x, Index t) {
        using T = ScalarOf<decltype(x)>;
        Eigen::Matrix<T, 2, 2> edges;
        edges << x[2] - x[0], x[4] - x[0], x[3] - x[1], x[5] - x[1];
        const Eigen::Matrix<T, 2, 2> J = edges * data.rest_inverse[t];
        const T det = J.determinant();
        if (det <= 0.0) return T(kInfinity);
        return T(data.area[t] * J.squaredNorm() * (1.0 + 1.0 / (det * det)));
    };
}

TriangleData one_triangle() {
    Eigen::Matrix2d rest;
    rest << 1.0, 0.3, 0.0, 0.8;
    return {{rest.inverse()}, {0.5 * rest.determinant()}};
}

/// The same links as a struct.
struct Spring : AutodiffEnergy<Spring, 2> {
    template <class T>
    T energy(Index e, const Eigen::Matrix<T, 2, 1>& x) const {
        const T d = x[1] - x[0] - 1.0 - 0.1 * e;
        return d * d + 0.1 * d * d * d * d;
    }
};

/// A weight per element, and how many elements it covers.
struct Weighted : AutodiffEnergy<Weighted, 1> {
    std::vector<double> weight;
    Index num_elements() const { return Index(weight.size()); }
    template <class T>
    T energy(Index e, const Eigen::Matrix<T, 1, 1>& x) const {
        return weight[e] * x[0] * x[0];
    }
};

TEST(LambdaEnergy, GradientAndHessianMatchFiniteDifferences) {
    const TriangleData data = one_triangle();
    const auto energy = lambda_energy<6>(symmetric_dirichlet(data));
    Vec<6> x;
    x << 0.1, -0.2, 1.3, 0.1, 0.2, 0.9;
    const DerivativeCheck check = check_derivatives(energy, 0, x);
    EXPECT_GT(check.value, 0.0);
    EXPECT_TRUE(check.passes(1e-6))
        << check.gradient_error << ' ' << check.hessian_error << ' ' << check.asymmetry;
    // The value path (double) and the derivative path (Dual) give the same value.
    EXPECT_DOUBLE_EQ(energy.value(0, x), check.value);
}

TEST(LambdaEnergy, AnInvertedElementIsInfeasible) {
    const TriangleData data = one_triangle();
    const auto energy = lambda_energy<6>(symmetric_dirichlet(data));
    Vec<6> flipped;
    flipped << 0.0, 0.0, 0.0, 1.0, 1.0, 0.0;
    EXPECT_EQ(energy.value(0, flipped), kInfinity);
}

TEST(LambdaEnergy, SolvesAsTheSameEnergyWrittenAsAStruct) {
    auto make = [] {
        Problem problem(Eigen::VectorXd::LinSpaced(6, 0.0, 2.0));
        problem.set_fixed(0);
        return problem;
    };
    std::vector<std::array<Index, 2>> links = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}};
    Problem by_struct = make(), by_lambda = make();
    by_struct.add_term("springs", Spring{}, links);
    by_lambda.add_elements<2>("springs", links, [](auto const& x, Index e) {
        const auto d = x[1] - x[0] - 1.0 - 0.1 * e;
        return d * d + 0.1 * d * d * d * d;
    });
    const NewtonSummary a = solve(by_struct), b = solve(by_lambda);
    ASSERT_TRUE(a.success());
    EXPECT_EQ(a.num_steps(), b.num_steps());
    EXPECT_EQ(by_struct.variables(), by_lambda.variables());  // the same bits
    EXPECT_NEAR(by_lambda.variables()[5], 5.0 + 0.1 * 10, 1e-6);
}

TEST(LambdaEnergy, PerElementDataOfTheWrongSizeIsRejected) {
    Problem problem(Eigen::VectorXd::Zero(4));
    const std::vector<double> rest = {1.0, 2.0};  // for two elements; three are given
    const Eigen::MatrixXd targets = Eigen::MatrixXd::Zero(3, 2);
    const std::vector<std::array<Index, 2>> links = {{0, 1}, {1, 2}, {2, 3}};
    auto f = [&](auto const& x, Index e) { return (x[1] - x[0] - rest[e]) * (x[1] - x[0]); };
    try {
        problem.add_elements<2>("links", links, per_element(targets, rest), f);
        FAIL() << "expected InvalidArgumentError";
    } catch (const InvalidArgumentError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("'links'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("array 2 of 2"), std::string::npos) << msg;
        EXPECT_NE(msg.find("2 entries for 3 elements"), std::string::npos) << msg;
    }
    EXPECT_EQ(problem.num_terms(), 0);
    // The right sizes pass; so does no declaration at all.
    problem.add_elements<2>("links", {{0, 1}, {1, 2}}, per_element(rest), f);
    EXPECT_EQ(problem.num_terms(), 1);
}

TEST(LambdaEnergy, AStructsElementCountIsCheckedAgainstItsElements) {
    Problem problem(Eigen::VectorXd::Zero(3));
    Weighted energy;
    energy.weight = {1.0, 2.0};
    EXPECT_THROW(problem.add_term("weighted", energy, {{0}, {1}, {2}}), InvalidArgumentError);
    EXPECT_NO_THROW(problem.add_term("weighted", energy, {{0}, {1}}));
}

}  // namespace
}  // namespace sa
