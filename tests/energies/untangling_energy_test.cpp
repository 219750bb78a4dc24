// The regularized untangling energy (energies/untangling_energy.h) and the barrier's continuation
// beyond its exponent cap (energies/barrier.h).

#include "energies/untangling_energy.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <memory>
#include <random>

#include "energies/barrier.h"
#include "energies/simplex_energy.h"
#include "optim/derivative_check.h"
#include "optim/dual.h"

namespace sa {
namespace {

template <int D>
Vec<D * D> random_matrix(std::mt19937& rng, double scale = 1.0) {
    std::normal_distribution<double> normal;
    Vec<D * D> a;
    for (int k = 0; k < D * D; ++k) a[k] = scale * normal(rng);
    return a;
}

TEST(RegularizedDeterminant, MatchesItsDefinitionAndDerivatives) {
    for (double eps : {1.0, 1e-3}) {
        for (double J : {-50.0, -1.0, -1e-4, 0.0, 1e-4, 0.7, 30.0}) {
            const Chi c = regularized_determinant(J, eps);
            const double r = std::sqrt(eps * eps + J * J);
            EXPECT_NEAR(c.value, 0.5 * (J + r), 1e-12 * std::max(1.0, r));
            EXPECT_GT(c.value, 0.0);
            const double h = 1e-6 * std::max(1.0, std::abs(J));
            const double first = (regularized_determinant(J + h, eps).value -
                                  regularized_determinant(J - h, eps).value) /
                                 (2 * h);
            const double second = (regularized_determinant(J + h, eps).first -
                                   regularized_determinant(J - h, eps).first) /
                                  (2 * h);
            EXPECT_NEAR(c.first, first, 1e-6);
            EXPECT_NEAR(c.second, second, 1e-5 * std::max(1.0, std::abs(c.second)));
        }
    }
    // Far on the inverted side the naive (J + r) / 2 is 0; the stable form is eps^2 / (4 |J|).
    EXPECT_NEAR(regularized_determinant(-1e9, 1e-3).value, 1e-6 / 4e9, 1e-25);
}

template <int D>
void check_untangling_derivatives() {
    std::mt19937 rng(7);
    auto parameters = std::make_shared<UntanglingParameters>();
    const UntanglingEnergy<D> energy({2.0}, parameters);
    for (double eps : {1.0, 0.05}) {
        parameters->epsilon = eps;
        for (int trial = 0; trial < 30; ++trial) {
            const Vec<D* D> a = random_matrix<D>(rng);  // either orientation
            EXPECT_TRUE(check_derivatives(energy, 0, a).passes(1e-5))
                << "D " << D << " eps " << eps << " trial " << trial;
            EXPECT_TRUE(std::isfinite(energy.value(0, a)));
        }
    }
}

TEST(UntanglingEnergy, DerivativesMatchFiniteDifferences) {
    check_untangling_derivatives<2>();
    check_untangling_derivatives<3>();
}

template <int D>
void check_projection() {
    std::mt19937 rng(11);
    auto parameters = std::make_shared<UntanglingParameters>();
    parameters->epsilon = 0.1;
    const UntanglingEnergy<D> energy({1.0}, parameters);
    for (int trial = 0; trial < 40; ++trial) {
        const Vec<D* D> a = random_matrix<D>(rng);
        Vec<D * D> g;
        Mat<D * D> h;
        energy.value_gradient_hessian(0, a, g, h);
        energy.project_hessian(0, a, h, ProjectionMode::kClamp, 1e-8);
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(h, Eigen::EigenvaluesOnly);
        EXPECT_GE(eig.eigenvalues().minCoeff(), 1e-8 * (1.0 - 1e-6) - 1e-9 * h.norm())
            << "D " << D << " trial " << trial;
    }
}

TEST(UntanglingEnergy, ProjectedHessianIsPositiveDefinite) {
    check_projection<2>();
    check_projection<3>();
}

TEST(UntanglingEnergy, InvertedSimplicesCostMoreAsEpsilonShrinks) {
    auto parameters = std::make_shared<UntanglingParameters>();
    const UntanglingEnergy<3> energy({1.0}, parameters);
    Mat<3> inverted = Mat<3>::Identity();
    inverted(2, 2) = -0.5;
    const Vec<9> a = Eigen::Map<const Vec<9>>(inverted.data());
    const Mat<3> I = Mat<3>::Identity();
    const Vec<9> identity = Eigen::Map<const Vec<9>>(I.data());
    double previous = 0.0;
    for (double eps : {1.0, 0.1, 0.01, 1e-3}) {
        parameters->epsilon = eps;
        const double e = energy.value(0, a);
        EXPECT_GT(e, previous);
        previous = e;
    }
    // At the identity and eps -> 0 the energy is its minimum: (1 - theta) 3 + theta 2.
    parameters->epsilon = 1e-10;
    EXPECT_NEAR(energy.value(0, identity), 0.5 * 3.0 + 0.5 * 2.0, 1e-9);
}

TEST(Barrier, ContinuesQuadraticallyBeyondTheExponentCap) {
    BarrierOptions options;
    const double c = kBarrierExponentCap;
    // Value, slope and curvature agree at the cap (Dual<1> in d).
    const Dual<1> below = barrier(Dual<1>::variable(c - 1e-9, 0), options);
    const Dual<1> above = barrier(Dual<1>::variable(c + 1e-9, 0), options);
    EXPECT_NEAR(above.value / below.value, 1.0, 1e-8);
    EXPECT_NEAR(above.gradient[0] / below.gradient[0], 1.0, 1e-8);
    EXPECT_NEAR(above.hessian(0, 0) / below.hessian(0, 0), 1.0, 1e-8);
    // Finite far beyond, increasing, and e^{s d} itself below the cap.
    EXPECT_TRUE(std::isfinite(barrier(1e6, options)));
    EXPECT_GT(barrier(2e6, options), barrier(1e6, options));
    EXPECT_DOUBLE_EQ(barrier(3.0, options), std::exp(3.0));
    // A simplex of conformal distortion 2e4 (far past e^709) is feasible for the energy.
    SimplexEnergyOptions o;
    const SimplexEnergy<3> energy(o, {1.0});
    Mat<3> flat = Mat<3>::Identity();
    flat(2, 2) = 0.01;
    EXPECT_TRUE(std::isfinite(energy.value(0, Eigen::Map<const Vec<9>>(flat.data()))));
}

}  // namespace
}  // namespace sa
