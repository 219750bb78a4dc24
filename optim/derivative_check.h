#pragma once
// Finite-difference checks of an element energy's derivatives, for tests of any energy:
//   gradient against central differences of value(),
//   Hessian against central differences of the analytic gradient, and its symmetry.
// For an energy of run-time arity with a hessian_block B, only the diagonal B x B blocks are
// compared (the others are not computed).
// Errors are relative: max |analytic - numeric| / max(1, max |analytic|).

#include <algorithm>
#include <cmath>

#include "optim/dynamic_element_energy.h"
#include "optim/element_energy.h"

namespace sa {

struct DerivativeCheck {
    double value = 0.0;
    double gradient_error = 0.0;
    double hessian_error = 0.0;
    double asymmetry = 0.0;  ///< max |H - H^T| / max(1, max |H|)
    bool passes(double tolerance) const {
        return gradient_error <= tolerance && hessian_error <= tolerance && asymmetry <= tolerance;
    }
};

/// Checks element `element` of `energy` at `x` with central differences of step
/// h * max(1, |x_i|).
template <ElementEnergy E>
DerivativeCheck check_derivatives(const E& energy, Index element, const Vec<E::arity>& x,
                                  double h = 1e-6) {
    constexpr int N = E::arity;
    DerivativeCheck check;
    Vec<N> g;
    Mat<N> H;
    check.value = energy.value_gradient_hessian(element, x, g, H);
    Vec<N> g_numeric;
    Mat<N> H_numeric;
    for (int i = 0; i < N; ++i) {
        const double step = h * std::max(1.0, std::abs(x[i]));
        Vec<N> xp = x, xm = x;
        xp[i] += step;
        xm[i] -= step;
        g_numeric[i] = (energy.value(element, xp) - energy.value(element, xm)) / (2.0 * step);
        Vec<N> gp, gm;
        Mat<N> unused;
        energy.value_gradient_hessian(element, xp, gp, unused);
        energy.value_gradient_hessian(element, xm, gm, unused);
        H_numeric.col(i) = (gp - gm) / (2.0 * step);
    }
    const double g_scale = std::max(1.0, g.cwiseAbs().maxCoeff());
    const double h_scale = std::max(1.0, H.cwiseAbs().maxCoeff());
    check.gradient_error = (g - g_numeric).cwiseAbs().maxCoeff() / g_scale;
    check.hessian_error = (H - H_numeric).cwiseAbs().maxCoeff() / h_scale;
    check.asymmetry = (H - H.transpose()).cwiseAbs().maxCoeff() / h_scale;
    return check;
}

/// The same for element `element` of an energy of run-time arity at `x` (its arity).
template <DynamicElementEnergy E>
DerivativeCheck check_derivatives(const E& energy, Index element, const Eigen::VectorXd& x,
                                  double h = 1e-6) {
    constexpr int B = dynamic_hessian_block_of<E>();
    const Eigen::Index n = x.size(), rows = B > 0 ? B : n;
    // The B x n blocks side by side as an n x n matrix (zero off the blocks).
    auto dense = [&](const Eigen::MatrixXd& blocks) {
        if (B == 0) return blocks;
        Eigen::MatrixXd full = Eigen::MatrixXd::Zero(n, n);
        for (Eigen::Index k = 0; k < n / rows; ++k)
            full.block(rows * k, rows * k, rows, rows) = blocks.middleCols(rows * k, rows);
        return full;
    };
    DerivativeCheck check;
    Eigen::VectorXd g(n);
    Eigen::MatrixXd blocks(rows, n);
    check.value = energy.value_gradient_hessian(element, x, g, blocks);
    const Eigen::MatrixXd H = dense(blocks);
    Eigen::VectorXd g_numeric(n);
    Eigen::MatrixXd H_numeric(n, n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double step = h * std::max(1.0, std::abs(x[i]));
        Eigen::VectorXd xp = x, xm = x;
        xp[i] += step;
        xm[i] -= step;
        g_numeric[i] = (energy.value(element, xp) - energy.value(element, xm)) / (2.0 * step);
        Eigen::VectorXd gp(n), gm(n);
        Eigen::MatrixXd unused(rows, n);
        energy.value_gradient_hessian(element, xp, gp, unused);
        energy.value_gradient_hessian(element, xm, gm, unused);
        H_numeric.col(i) = (gp - gm) / (2.0 * step);
        if (B > 0) {  // only the block of column i
            const Eigen::Index first = i - i % rows;
            for (Eigen::Index r = 0; r < n; ++r)
                if (r < first || r >= first + rows) H_numeric(r, i) = 0.0;
        }
    }
    const double g_scale = std::max(1.0, g.cwiseAbs().maxCoeff());
    const double h_scale = std::max(1.0, H.cwiseAbs().maxCoeff());
    check.gradient_error = (g - g_numeric).cwiseAbs().maxCoeff() / g_scale;
    check.hessian_error = (H - H_numeric).cwiseAbs().maxCoeff() / h_scale;
    check.asymmetry = (H - H.transpose()).cwiseAbs().maxCoeff() / h_scale;
    return check;
}

}  // namespace sa
