#include "optim/anderson_acceleration.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "optim/errors.h"

namespace sa {
namespace {

// G(x) = M x + b with M symmetric, eigenvalues in [0, 0.99]: plain iteration contracts by 0.99
// per step at worst; the fixed point solves (I - M) x = b.
struct SlowLinearMap {
    Eigen::MatrixXd M;
    Eigen::VectorXd b, fixed_point;
    explicit SlowLinearMap(int n) {
        Eigen::MatrixXd Q =
            Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(n, n)).householderQ();
        Eigen::VectorXd eigenvalues = Eigen::VectorXd::LinSpaced(n, 0.0, 0.99);
        M = Q * eigenvalues.asDiagonal() * Q.transpose();
        b = Eigen::VectorXd::Random(n);
        fixed_point = (Eigen::MatrixXd::Identity(n, n) - M).lu().solve(b);
    }
    Eigen::VectorXd operator()(const Eigen::VectorXd& x) const { return M * x + b; }
};

TEST(AndersonAcceleration, ReachesTheFixedPointWherePlainIterationCreeps) {
    const SlowLinearMap G(40);
    Eigen::VectorXd plain = Eigen::VectorXd::Zero(40), accelerated = plain;
    AndersonAcceleration anderson(8);
    for (int k = 0; k < 80; ++k) {
        plain = G(plain);
        accelerated = anderson.next(accelerated, G(accelerated));
    }
    // Plain: at worst 0.99^80 = 0.45 of the start's error; accelerated: orders of magnitude less.
    const double plain_error = (plain - G.fixed_point).norm();
    EXPECT_GT(plain_error, 0.1 * G.fixed_point.norm());
    EXPECT_LT((accelerated - G.fixed_point).norm(), 1e-3 * plain_error);
}

TEST(AndersonAcceleration, FirstStepAndStepAfterResetArePlain) {
    const SlowLinearMap G(10);
    AndersonAcceleration anderson(3);
    const Eigen::VectorXd x0 = Eigen::VectorXd::Ones(10);
    EXPECT_EQ(anderson.next(x0, G(x0)), G(x0));
    const Eigen::VectorXd x1 = G(x0);
    EXPECT_NE(anderson.next(x1, G(x1)), G(x1));
    anderson.reset();
    EXPECT_EQ(anderson.next(x1, G(x1)), G(x1));
}

TEST(AndersonAcceleration, RejectsAnEmptyHistory) {
    EXPECT_THROW(AndersonAcceleration(0), InvalidArgumentError);
}

}  // namespace
}  // namespace sa
