// A user's program on the installed optimizer alone: a chain of springs (a lambda energy) between
// two pinned ends, sagging under gravity (a struct). Exits 0 when the solve converged to a
// symmetric, sagging equilibrium.
#include <cmath>
#include <iostream>

#include "optim/optim.h"

struct Gravity : sa::AutodiffEnergy<Gravity, 1> {
    static constexpr bool is_quadratic = true;
    template <class T>
    T energy(sa::Index, const Eigen::Matrix<T, 1, 1>& y) const {
        return y[0];
    }
};

int main() {
    const int n = 11;  // points 0..n-1 on [0, 1]
    Eigen::VectorXd x(2 * n);
    for (int i = 0; i < n; ++i) x.segment<2>(2 * i) << double(i) / (n - 1), 0.0;
    sa::Problem problem(x);
    std::vector<std::array<sa::Index, 4>> springs;
    std::vector<std::array<sa::Index, 1>> heights;
    for (int i = 0; i + 1 < n; ++i) springs.push_back({2 * i, 2 * i + 1, 2 * i + 2, 2 * i + 3});
    for (int i = 0; i < n; ++i) heights.push_back({2 * i + 1});
    const double rest = 0.8 / (n - 1);
    problem.add_elements<4>("springs", springs, [rest](auto const& x, sa::Index) {
        using std::sqrt;
        const auto dx = x[2] - x[0], dy = x[3] - x[1];
        const auto stretch = sqrt(dx * dx + dy * dy) - rest;
        return 50.0 * stretch * stretch;
    });
    problem.add_term("gravity", Gravity{}, heights, 0.1);
    for (int k : {0, 1, 2 * n - 2, 2 * n - 1}) problem.set_fixed(k);

    const sa::NewtonSummary summary = sa::solve(problem);
    std::cout << summary.brief_report() << '\n';
    // At equilibrium the chain is symmetric and sags: the middle point is lowest.
    const Eigen::VectorXd& y = problem.variables();
    const double middle = y[2 * (n / 2) + 1];
    const bool symmetric = std::abs(y[3] - y[2 * n - 3]) < 1e-8;
    std::cout << "middle point at height " << middle << '\n';
    return summary.success() && symmetric && middle < 0.0 ? 0 : 1;
}
