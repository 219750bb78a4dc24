#pragma once
// Small element energies used by the optimizer tests.

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "optim/optim.h"

namespace sa::test {

/// 0.5 * c * (x - target)^2 on one variable: quadratic, constant Hessian.
struct Parabola : AutodiffEnergy<Parabola, 1> {
    static constexpr bool is_quadratic = true;
    std::vector<double> curvature, target;
    template <class T>
    T energy(Index e, const Eigen::Matrix<T, 1, 1>& x) const {
        return 0.5 * curvature[e] * (x[0] - target[e]) * (x[0] - target[e]);
    }
};

/// 0.5 * c * (x_i - x_j)^2: a spring between two variables.
struct Spring : AutodiffEnergy<Spring, 2> {
    double stiffness = 1.0;
    template <class T>
    T energy(Index, const Eigen::Matrix<T, 2, 1>& x) const {
        return 0.5 * stiffness * (x[0] - x[1]) * (x[0] - x[1]);
    }
};

/// One link of the Rosenbrock chain: 100 (x_{i+1} - x_i^2)^2 + (1 - x_i)^2. Non-convex.
struct RosenbrockLink : AutodiffEnergy<RosenbrockLink, 2> {
    template <class T>
    T energy(Index, const Eigen::Matrix<T, 2, 1>& x) const {
        const T a = x[1] - x[0] * x[0], b = 1.0 - x[0];
        return 100.0 * a * a + b * b;
    }
};

/// c * x - log(x) on one variable, +inf for x <= 0; minimum at x = 1 / c. Counts evaluations
/// at infeasible points. With `provide_max_step`, the line search is told where x reaches 0.
template <bool provide_max_step>
struct LogBarrierT {
    static constexpr int arity = 1;
    double c = 1.0;
    std::atomic<int>* infeasible_evaluations = nullptr;

    double value(Index, const Vec<1>& x) const {
        if (x[0] <= 0.0) {
            if (infeasible_evaluations) ++*infeasible_evaluations;
            return kInfinity;
        }
        return c * x[0] - std::log(x[0]);
    }
    double value_gradient_hessian(Index e, const Vec<1>& x, Vec<1>& g, Mat<1>& h) const {
        const double v = value(e, x);
        g[0] = c - 1.0 / x[0];
        h(0, 0) = 1.0 / (x[0] * x[0]);
        return v;
    }
};
struct LogBarrier : LogBarrierT<true> {
    double max_step(Index, const Vec<1>& x, const Vec<1>& dx) const {
        return dx[0] < 0.0 ? -x[0] / dx[0] : kInfinity;
    }
};
using LogBarrierWithoutMaxStep = LogBarrierT<false>;

/// (x^2 - 1)^2 / 4 + s x: a double well, indefinite between the wells.
struct DoubleWell : AutodiffEnergy<DoubleWell, 1> {
    double tilt = 0.0;
    template <class T>
    T energy(Index, const Eigen::Matrix<T, 1, 1>& x) const {
        const T a = x[0] * x[0] - 1.0;
        return 0.25 * a * a + tilt * x[0];
    }
};

/// A spring that throws while `armed` is set, to test that errors reach the caller.
struct ThrowingSpring : AutodiffEnergy<ThrowingSpring, 2> {
    const std::atomic<bool>* armed = nullptr;
    template <class T>
    T energy(Index, const Eigen::Matrix<T, 2, 1>& x) const {
        if (armed != nullptr && armed->load()) {
            throw std::runtime_error("element evaluation failed on purpose");
        }
        return 0.5 * (x[0] - x[1]) * (x[0] - x[1]);
    }
};

}  // namespace sa::test
