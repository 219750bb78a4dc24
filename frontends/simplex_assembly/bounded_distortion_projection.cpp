#include "frontends/simplex_assembly/bounded_distortion_projection.h"

#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "optim/errors.h"

namespace sa {

namespace {

template <int D>
double clamp_cost(const Vec<D>& sigma, double K, double t) {
    double f = 0.0;
    for (int i = 0; i < D; ++i) {
        if (sigma[i] < t) f += (t - sigma[i]) * (t - sigma[i]);
        if (sigma[i] > K * t) f += (sigma[i] - K * t) * (sigma[i] - K * t);
    }
    return f;
}

}  // namespace

template <int D>
Vec<D> clamp_singular_values(const Vec<D>& sigma, double K) {
    const double lo = sigma.minCoeff(), hi = sigma.maxCoeff();
    if (!(hi > 0.0) || std::isinf(K) || hi <= K * lo) return sigma;
    // Breakpoints of f: where some sigma_i enters the low set (t = sigma_i) or leaves the high
    // set (t = sigma_i / K). On each interval between consecutive ones both sets are fixed and
    // f is a quadratic whose minimizer is t = (sum_L sigma + K sum_H sigma) / (|L| + K^2 |H|).
    std::array<double, 2 * D + 2> breaks;
    int n = 0;
    breaks[n++] = 0.0;
    for (int i = 0; i < D; ++i) {
        breaks[n++] = sigma[i];
        breaks[n++] = sigma[i] / K;
    }
    breaks[n++] = hi;  // beyond it every sigma_i is below t: f only grows
    std::sort(breaks.begin(), breaks.begin() + n);
    double best_t = hi / K, best_f = clamp_cost<D>(sigma, K, best_t);
    for (int j = 0; j + 1 < n; ++j) {
        const double a = breaks[j], b = breaks[j + 1];
        if (!(b > a)) continue;
        const double mid = 0.5 * (a + b);
        double numerator = 0.0, denominator = 0.0;
        for (int i = 0; i < D; ++i) {
            if (sigma[i] < mid) {
                numerator += sigma[i];
                denominator += 1.0;
            }
            if (sigma[i] > K * mid) {
                numerator += K * sigma[i];
                denominator += K * K;
            }
        }
        const double t = denominator > 0.0 ? std::clamp(numerator / denominator, a, b) : mid;
        const double f = clamp_cost<D>(sigma, K, t);
        if (f < best_f) {
            best_f = f;
            best_t = t;
        }
    }
    Vec<D> clamped;
    for (int i = 0; i < D; ++i) clamped[i] = std::clamp(sigma[i], best_t, K * best_t);
    return clamped;
}

template <int D>
Mat<D> project_bounded_distortion(const Mat<D>& A, double K) {
    if (!(K >= 1.0)) {
        throw InvalidArgumentError("project_bounded_distortion: bound K = " + std::to_string(K) +
                                   " must be >= 1");
    }
    if (!A.allFinite())
        throw InvalidArgumentError("project_bounded_distortion: the matrix is not finite");
    const Eigen::JacobiSVD<Mat<D>> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Vec<D>& sigma = svd.singularValues();  // decreasing
    const double det = A.determinant();
    if (det > 0.0 && sigma[0] <= K * sigma[D - 1]) return A;
    if (!(sigma[0] > 0.0)) return A;  // the zero matrix
    Mat<D> U = svd.matrixU();
    const Mat<D>& V = svd.matrixV();
    if ((U * V.transpose()).determinant() < 0.0) U.col(D - 1) *= -1.0;  // smallest direction
    return U * clamp_singular_values<D>(sigma, K).asDiagonal() * V.transpose();
}

double largest_conformal_distortion(double K, int d) {
    if (!(K >= 1.0) || (d != 2 && d != 3)) {
        throw InvalidArgumentError("largest_conformal_distortion: K = " + std::to_string(K) +
                                   ", d = " + std::to_string(d) + " (expected K >= 1, d 2 or 3)");
    }
    if (std::isinf(K)) return kInfinity;
    // In 2D d^c = (r + 1/r) / 2 with r = s_max / s_min <= K. In 3D the closed form
    // (|A|^2 |A^-1|^2 - 1) / 8 = (sum over the pairs of (r_kl + 1/r_kl)^2 - 4) / 8, with ratios
    // a, b and ab <= K: at ab = K the sum is convex and symmetric in a over [1, K], largest at
    // a = 1 or a = K, i.e. at diag(K, 1, 1): 2 (K + 1/K)^2 / 8.
    const double pair = 0.5 * (K + 1.0 / K);
    return d == 2 ? pair : pair * pair;
}

template Vec<2> clamp_singular_values<2>(const Vec<2>&, double);
template Vec<3> clamp_singular_values<3>(const Vec<3>&, double);
template Mat<2> project_bounded_distortion<2>(const Mat<2>&, double);
template Mat<3> project_bounded_distortion<3>(const Mat<3>&, double);

}  // namespace sa
