#include "energies/boundary_angle_energy.h"

#include <gtest/gtest.h>

#include <array>
#include <random>

#include "optim/derivative_check.h"
#include "optim/dual.h"
#include "optim/problem_evaluation.h"

namespace sa {
namespace {

// A boundary vertex at `center` with a fan of K = degrees.size() - 1 triangles whose neighbours
// lie at the given angles (degrees) and distances from it: the vertex form's 2 K + 4 variables.
Eigen::VectorXd fan_positions(const std::vector<double>& degrees,
                              const std::vector<double>& radii = {},
                              const Vec<2>& center = Vec<2>::Zero()) {
    Eigen::VectorXd x(2 * degrees.size() + 2);
    x.head<2>() = center;
    for (std::size_t m = 0; m < degrees.size(); ++m) {
        const double t = degrees[m] * M_PI / 180.0, r = radii.empty() ? 1.0 : radii[m];
        x.segment<2>(2 + 2 * m) = center + r * Vec<2>(std::cos(t), std::sin(t));
    }
    return x;
}

TEST(BoundaryAngleEnergy, VertexFormIsOneOverTheAngleGap) {
    const BoundaryAngleVertexEnergy energy;
    EXPECT_NEAR(energy.value(0, fan_positions({0.0, 60.0, 120.0, 200.0})),
                1.0 / (2.0 * M_PI - 200.0 * M_PI / 180.0), 1e-12);
    EXPECT_NEAR(energy.value(0, fan_positions({0.0, 100.0, 200.0, 300.0, 359.0})),
                1.0 / (M_PI / 180.0), 1e-9);
    EXPECT_EQ(energy.value(0, fan_positions({0.0, 100.0, 200.0, 300.0, 361.0})), kInfinity);
}

TEST(BoundaryAngleEnergy, DerivativesMatchFiniteDifferences) {
    Eigen::VectorXd x = fan_positions({0.0, 60.0, 120.0, 200.0});
    x.head<2>() = Vec<2>(0.1, -0.05);
    EXPECT_TRUE(check_derivatives(BoundaryAngleVertexEnergy{}, 0, x).passes(1e-6));

    // The same fan as linear maps of three rest triangles with edges e0, e1 at v.
    BoundaryAngleEnergy energy;
    std::vector<Mat<2>>& edges = energy.edges.emplace_back(2);
    edges[0] << 1.0, 0.5, 0.0, 0.9;
    edges[1] << 0.5, -0.4, 0.9, 0.8;
    Eigen::VectorXd a(8);
    a << 1.1, 0.2, -0.1, 0.9, 0.8, 0.1, 0.3, 1.2;
    EXPECT_TRUE(check_derivatives(energy, 0, a).passes(1e-6));
}

/// Linear parts A_k = P_k E_k^-1 mapping arbitrary rest edges E_k of fan triangle k onto the
/// vertex form's edges P_k = (p_{k+1} - v, p_{k+2} - v) at x: the A-form of the same fan, its
/// rest edges added to `energy`.
Eigen::VectorXd linear_form(const Eigen::VectorXd& x, BoundaryAngleEnergy& energy,
                            std::mt19937& random) {
    std::uniform_real_distribution<double> shear(-0.3, 0.3);
    const int K = int(x.size() - 4) / 2;
    std::vector<Mat<2>>& edges = energy.edges.emplace_back(K);
    Eigen::VectorXd a(4 * K);
    for (int k = 0; k < K; ++k) {
        edges[k] << 1.0, shear(random), shear(random), 1.0;
        Mat<2> images;
        images.col(0) = x.segment<2>(2 + 2 * k) - x.head<2>();
        images.col(1) = x.segment<2>(4 + 2 * k) - x.head<2>();
        const Mat<2> A = images * edges[k].inverse();
        a.segment<4>(4 * k) = Eigen::Map<const Vec<4>>(A.data());
    }
    return a;
}

TEST(BoundaryAngleEnergy, LinearFormAgreesWithVertexForm) {
    std::mt19937 random(3);
    const Eigen::VectorXd x = fan_positions({0.0, 60.0, 120.0, 200.0});
    BoundaryAngleEnergy linear;
    const Eigen::VectorXd a = linear_form(x, linear, random);
    EXPECT_NEAR(linear.value(0, a), BoundaryAngleVertexEnergy{}.value(0, x), 1e-12);
}

// A fan of K triangles around a vertex near the origin, its K + 1 neighbours at random angles
// spanning up to 330 degrees and random distances, some triangles folded (a neighbour before the
// previous one).
Eigen::VectorXd random_fan(int K, std::mt19937& random) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> degrees{0.0}, radii{0.5 + unit(random)};
    const double step = 330.0 / K;
    for (int m = 1; m <= K; ++m) {
        const double back = unit(random) < 0.1 ? -1.5 : 0.0;  // a folded triangle
        degrees.push_back(degrees.back() + step * (0.2 + 0.8 * unit(random) + back));
        radii.push_back(0.5 + unit(random));
    }
    return fan_positions(degrees, radii, Vec<2>(0.1 * unit(random), -0.1 * unit(random)));
}

// The A-form's derivatives on fans of 3 to 40 triangles (up to 160 variables).
TEST(BoundaryAngleEnergy, LinearFormDerivativesOnFansOfAnySize) {
    std::mt19937 random(7);
    for (const int K : {3, 5, 12, 13, 27, 40}) {
        BoundaryAngleEnergy energy;
        const Eigen::VectorXd a = linear_form(random_fan(K, random), energy, random);
        const DerivativeCheck check = check_derivatives(energy, 0, a);
        EXPECT_TRUE(std::isfinite(check.value)) << K;
        EXPECT_TRUE(check.passes(1e-6)) << K << ": " << check.gradient_error << " "
                                        << check.hessian_error << " " << check.asymmetry;
    }
}

/// The vertex-form barrier of a fan of K triangles at fixed size 2 K + 4: the reference of the
/// next test, with its derivatives from those of each triangle's angle by automatic
/// differentiation (over the triangle's 6 variables), summed by the chain rule.
template <int K>
struct FixedSizeFan {
    static constexpr int arity = 2 * K + 4;

    /// The angle at v of triangle k, from (v, p_{k+1}, p_{k+2}).
    template <class T>
    static T angle(const Eigen::Matrix<T, 6, 1>& y) {
        using std::atan2;
        const T ax = y[2] - y[0], ay = y[3] - y[1], bx = y[4] - y[0], by = y[5] - y[1];
        return atan2(ax * by - ay * bx, ax * bx + ay * by);
    }
    static Vec<6> triangle(const Vec<arity>& x, int k) {
        Vec<6> y;
        y << x[0], x[1], x.template segment<4>(2 + 2 * k);
        return y;
    }
    double value(Index, const Vec<arity>& x) const {
        double theta = 0.0;
        for (int k = 0; k < K; ++k) theta += angle(triangle(x, k));
        return theta < 2.0 * M_PI ? 1.0 / (2.0 * M_PI - theta) : kInfinity;
    }
    double value_gradient_hessian(Index, const Vec<arity>& x, Vec<arity>& g, Mat<arity>& h) const {
        double theta = 0.0;
        Vec<arity> dtheta = Vec<arity>::Zero();
        h.setZero();
        for (int k = 0; k < K; ++k) {
            const Dual<6> phi = angle(Dual<6>::variables(triangle(x, k)));
            theta += phi.value;
            const std::array<int, 6> at{0, 1, 2 + 2 * k, 3 + 2 * k, 4 + 2 * k, 5 + 2 * k};
            for (int i = 0; i < 6; ++i) {
                dtheta[at[i]] += phi.gradient[i];
                for (int j = 0; j < 6; ++j) h(at[i], at[j]) += phi.hessian(i, j);
            }
        }
        if (!(theta < 2.0 * M_PI)) return kInfinity;
        const double e = 1.0 / (2.0 * M_PI - theta);  // E' = E^2, E'' = 2 E^3
        g = e * e * dtheta;
        h = e * e * h + 2.0 * e * e * e * dtheta * dtheta.transpose();
        return e;
    }
};

template <int... K>
void add_fixed_size_terms(Problem& problem, const std::vector<std::vector<Index>>& fans) {
    (
        [&] {
            std::vector<std::array<Index, 2 * K + 4>> elements;
            for (const std::vector<Index>& fan : fans) {
                if (int(fan.size()) != 2 * K + 4) continue;
                std::array<Index, 2 * K + 4> e;
                std::copy(fan.begin(), fan.end(), e.begin());
                elements.push_back(e);
            }
            problem.add_term("fans of " + std::to_string(K), FixedSizeFan<K>{}, elements, 0.7);
        }(),
        ...);
}

// One term of run-time arity holding fans of 3 to 40 triangles gives the energy, gradient and
// projected Hessian that fixed-size terms of each size give (values to round-off: closed-form
// derivatives against automatic differentiation).
TEST(BoundaryAngleEnergy, RunTimeArityTermMatchesFixedSizeTerms) {
    std::mt19937 random(11);
    std::vector<std::vector<Index>> fans;
    std::vector<double> values;
    for (int round = 0; round < 3; ++round) {
        for (const int K : {3, 7, 12, 13, 24, 40}) {
            const Eigen::VectorXd x = random_fan(K, random);
            std::vector<Index>& fan = fans.emplace_back();
            for (Eigen::Index i = 0; i < x.size(); ++i) {
                fan.push_back(Index(values.size()));
                values.push_back(x[i]);
            }
        }
    }
    const Eigen::VectorXd x0 = Eigen::Map<const Eigen::VectorXd>(values.data(), values.size());
    Problem dynamic(x0), fixed(x0);
    RaggedElements elements;
    for (const auto& fan : fans) elements.push_back(fan);
    dynamic.add_term("fans", BoundaryAngleVertexEnergy{}, std::move(elements), 0.7);
    add_fixed_size_terms<3, 7, 12, 13, 24, 40>(fixed, fans);

    const ProblemEvaluation a = evaluate(dynamic, x0), b = evaluate(fixed, x0);
    ASSERT_TRUE(std::isfinite(b.value));
    EXPECT_NEAR(a.value, b.value, 1e-12 * std::abs(b.value));
    ASSERT_EQ(a.gradient.size(), b.gradient.size());
    EXPECT_LT((a.gradient - b.gradient).cwiseAbs().maxCoeff(),
              1e-10 * b.gradient.cwiseAbs().maxCoeff());
    const Eigen::MatrixXd ha(a.hessian), hb(b.hessian);
    EXPECT_LT((ha - hb).cwiseAbs().maxCoeff(), 1e-9 * hb.cwiseAbs().maxCoeff());
    // The projection did something: the raw Hessians are indefinite.
    const ProblemEvaluation raw = evaluate(fixed, x0, ProjectionMode::kNone);
    EXPECT_GT((Eigen::MatrixXd(raw.hessian) - hb).cwiseAbs().maxCoeff(),
              1e-3 * hb.cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace sa
