#include <gtest/gtest.h>

#include "optim/optim.h"

namespace sa {
namespace {

// Exercises every Dual operation inside one energy, checked against finite differences.
struct EveryOperation : AutodiffEnergy<EveryOperation, 3> {
    template <class T>
    T energy(Index, const Eigen::Matrix<T, 3, 1>& x) const {
        using std::acos, std::atan2, std::cos, std::exp, std::log, std::pow, std::sin, std::sqrt;
        const T a = x[0] * x[1] / x[2] + 2.0 / x[0] - (3.0 - x[1]);
        const T b = sqrt(x[0] * x[0] + 1.0) + exp(0.3 * x[1]) + log(x[2]) + pow(x[2], 2.5);
        const T c = sin(x[0]) * cos(x[1]) + acos(0.2 * x[2]) + atan2(x[1], x[0]);
        return a * b + c;
    }
};

TEST(Dual, DerivativesOfEveryOperationMatchFiniteDifferences) {
    const EveryOperation energy;
    for (const Vec<3>& x :
         {Vec<3>(0.7, 1.3, 2.1), Vec<3>(-1.1, 0.4, 0.9), Vec<3>(2.0, -0.5, 3.3)}) {
        const DerivativeCheck check = check_derivatives(energy, 0, x);
        EXPECT_TRUE(check.passes(1e-6))
            << "at " << x.transpose() << ": gradient error " << check.gradient_error
            << ", Hessian error " << check.hessian_error;
    }
}

TEST(Dual, WorksInsideEigenMatrices) {
    const Vec<4> x(1.0, 2.0, 3.0, 5.0);
    const auto d = Dual<4>::variables(x);
    Eigen::Matrix<Dual<4>, 2, 2> m;
    m << d[0], d[1], d[2], d[3];
    const Dual<4> det = m.determinant();
    EXPECT_DOUBLE_EQ(det.value, 1.0 * 5.0 - 2.0 * 3.0);
    EXPECT_EQ(det.gradient, Vec<4>(5.0, -3.0, -2.0, 1.0));
    const Dual<4> norm2 = m.squaredNorm();
    EXPECT_EQ(norm2.gradient, 2.0 * x);
    EXPECT_EQ(norm2.hessian, 2.0 * Mat<4>::Identity());
    const Eigen::Matrix<Dual<4>, 2, 2> inv = m.inverse();
    EXPECT_NEAR(inv(0, 0).value, 5.0 / det.value, 1e-15);
}

// A deliberately wrong gradient must be caught by the checker.
struct WrongGradient {
    static constexpr int arity = 2;
    double value(Index, const Vec<2>& x) const { return x.squaredNorm(); }
    double value_gradient_hessian(Index, const Vec<2>& x, Vec<2>& g, Mat<2>& h) const {
        g = 3.0 * x;  // should be 2 x
        h = 2.0 * Mat<2>::Identity();
        return x.squaredNorm();
    }
};

TEST(DerivativeCheck, DetectsAWrongGradientAndAWrongHessian) {
    const DerivativeCheck check = check_derivatives(WrongGradient{}, 0, Vec<2>(1.0, 2.0));
    EXPECT_GT(check.gradient_error, 0.1);
    EXPECT_GT(check.hessian_error, 0.1);  // numeric Hessian of the wrong gradient is 3 I
    EXPECT_FALSE(check.passes(1e-6));
}

}  // namespace
}  // namespace sa
