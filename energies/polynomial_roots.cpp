#include "energies/polynomial_roots.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sa {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double evaluate(double c0, double c1, double c2, double c3, double t) {
    return ((c3 * t + c2) * t + c1) * t + c0;
}

double polish(double c0, double c1, double c2, double c3, double t) {
    for (int k = 0; k < 4; ++k) {
        const double f = evaluate(c0, c1, c2, c3, t);
        const double df = (3.0 * c3 * t + 2.0 * c2) * t + c1;
        if (df == 0.0) break;
        const double next = t - f / df;
        if (!std::isfinite(next)) break;
        t = next;
    }
    return t;
}

/// Real roots of c0 + c1 t + c2 t^2 (c2 != 0), cancellation-free.
int quadratic_roots(double c0, double c1, double c2, double roots[2]) {
    const double disc = c1 * c1 - 4.0 * c2 * c0;
    if (disc < 0.0) return 0;
    const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
    int n = 0;
    if (q != 0.0) {
        roots[n++] = q / c2;
        roots[n++] = c0 / q;
    } else {
        roots[n++] = 0.0;  // c0 = c1 = 0
    }
    return n;
}

/// Real roots of t^3 + a t^2 + b t + c.
int monic_cubic_roots(double a, double b, double c, double roots[3]) {
    const double q = (a * a - 3.0 * b) / 9.0;
    const double r = (2.0 * a * a * a - 9.0 * a * b + 27.0 * c) / 54.0;
    const double q3 = q * q * q;
    if (r * r < q3) {  // three real roots (trigonometric form)
        const double theta = std::acos(std::clamp(r / std::sqrt(q3), -1.0, 1.0));
        const double m = -2.0 * std::sqrt(q);
        roots[0] = m * std::cos(theta / 3.0) - a / 3.0;
        roots[1] = m * std::cos((theta + 2.0 * M_PI) / 3.0) - a / 3.0;
        roots[2] = m * std::cos((theta - 2.0 * M_PI) / 3.0) - a / 3.0;
        return 3;
    }
    const double A = -std::copysign(std::cbrt(std::abs(r) + std::sqrt(r * r - q3)), r);
    const double B = A != 0.0 ? q / A : 0.0;
    roots[0] = (A + B) - a / 3.0;
    return 1;
}

}  // namespace

double smallest_positive_root(double c0, double c1, double c2, double c3) {
    const double scale = std::max({std::abs(c0), std::abs(c1), std::abs(c2), std::abs(c3)});
    if (scale == 0.0 || !std::isfinite(scale)) return kInf;
    constexpr double kNegligible = 1e-14;
    double roots[3];
    int n = 0;
    if (std::abs(c3) > kNegligible * scale) {
        n = monic_cubic_roots(c2 / c3, c1 / c3, c0 / c3, roots);
    } else if (std::abs(c2) > kNegligible * scale) {
        c3 = 0.0;
        n = quadratic_roots(c0, c1, c2, roots);
    } else if (std::abs(c1) > kNegligible * scale) {
        c3 = c2 = 0.0;
        roots[n++] = -c0 / c1;
    } else {
        return kInf;  // a nonzero constant
    }
    double best = kInf;
    for (int i = 0; i < n; ++i) {
        const double t = polish(c0, c1, c2, c3, roots[i]);
        if (t > 0.0 && t < best) best = t;
    }
    return best;
}

}  // namespace sa
