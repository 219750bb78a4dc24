#include "geometry/maps/rotation_fit.h"

#include <algorithm>
#include <cmath>

namespace sa {

namespace {

using Vec4 = Eigen::Matrix<double, 4, 1>;
using Mat4 = Eigen::Matrix<double, 4, 4>;

/// Newton iterations before the Jacobi iterations take over (one or two from a good hint).
constexpr int kMaxNewton = 6;
/// A Newton step of |v| below this is the last one: the error left after it (cubic in |v|, the
/// Rayleigh quotient's Newton iteration) is below round-off.
constexpr double kLastStep2 = 1e-10;  // |v|^2
/// The Hessian's LDL^T pivots must exceed this times |M|_F for the Newton result to stand.
constexpr double kPivot = 1e-4;

/// Horn's matrix: q^T N q = tr(R(q)^T M) for every unit quaternion q = (w, x, y, z).
Mat4 horn_matrix(const Mat<3>& M) {
    Mat4 N;
    N(0, 0) = M(0, 0) + M(1, 1) + M(2, 2);
    N(1, 1) = M(0, 0) - M(1, 1) - M(2, 2);
    N(2, 2) = -M(0, 0) + M(1, 1) - M(2, 2);
    N(3, 3) = -M(0, 0) - M(1, 1) + M(2, 2);
    N(0, 1) = N(1, 0) = M(2, 1) - M(1, 2);
    N(0, 2) = N(2, 0) = M(0, 2) - M(2, 0);
    N(0, 3) = N(3, 0) = M(1, 0) - M(0, 1);
    N(1, 2) = N(2, 1) = M(0, 1) + M(1, 0);
    N(1, 3) = N(3, 1) = M(0, 2) + M(2, 0);
    N(2, 3) = N(3, 2) = M(1, 2) + M(2, 1);
    return N;
}

/// The rotation of a unit quaternion (w, x, y, z).
Mat<3> rotation_of(const Vec4& q) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    Mat<3> R;
    R << w * w + x * x - y * y - z * z, 2.0 * (x * y - w * z), 2.0 * (x * z + w * y),
        2.0 * (x * y + w * z), w * w - x * x + y * y - z * z, 2.0 * (y * z - w * x),
        2.0 * (x * z - w * y), 2.0 * (y * z + w * x), w * w - x * x - y * y + z * z;
    return R;
}

/// The Hamilton product a b (the rotation of a after that of b).
Vec4 multiply(const Vec4& a, const Vec4& b) {
    return Vec4(a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
                a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
                a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
                a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]);
}

/// A start for M's quaternion: one power iteration on N(M) + sigma I (sigma = |M|_F / sqrt 3)
/// from the basis quaternion of N's largest diagonal entry. For M = s R(q), s > 0, it is q
/// exactly (N(sR) + s I = 4 s q q^T, as in Shepperd's method); the identity's when M = 0.
Vec4 start_quaternion(const Mat<3>& M) {
    Mat4 N = horn_matrix(M);
    int k = 0;
    for (int i = 1; i < 4; ++i) {
        if (N(i, i) > N(k, k)) k = i;
    }
    Vec4 q = N.col(k);
    q[k] += M.norm() / std::sqrt(3.0);
    const double norm = q.norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) return Vec4(1.0, 0.0, 0.0, 0.0);
    return q / norm;
}

/// The unit eigenvector of the largest eigenvalue of the symmetric N, by cyclic Jacobi
/// rotations; among equal largest eigenvalues, the first (e_0 when N is diagonal and N_00 is
/// largest).
Vec4 largest_eigenvector(Mat4 a) {
    Mat4 v = Mat4::Identity();
    const double total = a.squaredNorm();
    for (int sweep = 0; sweep < 50; ++sweep) {
        double off = 0.0;
        for (int p = 0; p < 4; ++p) {
            for (int q = p + 1; q < 4; ++q) off += a(p, q) * a(p, q);
        }
        if (!(off > 1e-34 * total)) break;
        for (int p = 0; p < 3; ++p) {
            for (int q = p + 1; q < 4; ++q) {
                const double apq = a(p, q);
                if (apq == 0.0) continue;
                const double theta = (a(q, q) - a(p, p)) / (2.0 * apq);
                const double t =
                    std::abs(theta) > 1e150
                        ? 0.5 / theta
                        : std::copysign(1.0, theta) / (std::abs(theta) + std::hypot(theta, 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 4; ++k) {  // columns p and q, then rows p and q
                    const double akp = a(k, p), akq = a(k, q);
                    a(k, p) = c * akp - s * akq;
                    a(k, q) = s * akp + c * akq;
                }
                for (int k = 0; k < 4; ++k) {
                    const double apk = a(p, k), aqk = a(q, k);
                    a(p, k) = c * apk - s * aqk;
                    a(q, k) = s * apk + c * aqk;
                }
                for (int k = 0; k < 4; ++k) {
                    const double vkp = v(k, p), vkq = v(k, q);
                    v(k, p) = c * vkp - s * vkq;
                    v(k, q) = s * vkp + c * vkq;
                }
            }
        }
    }
    int best = 0;
    for (int k = 1; k < 4; ++k) {
        if (a(k, k) > a(best, best)) best = k;
    }
    return v.col(best);
}

/// M's quaternion from the unit quaternion q (see the header).
Vec4 fit_quaternion(const Mat<3>& M, Vec4 q) {
    const double pivot = kPivot * M.norm();
    for (int iteration = 0; iteration < kMaxNewton; ++iteration) {
        const Mat<3> Mq = rotation_of(q).transpose() * M;
        const double t = Mq.trace();
        const Vec<3> g(Mq(2, 1) - Mq(1, 2), Mq(0, 2) - Mq(2, 0), Mq(1, 0) - Mq(0, 1));
        const Mat<3> H = 2.0 * t * Mat<3>::Identity() - Mq - Mq.transpose();
        // H = L diag(d) L^T, certified positive definite, and H v = g.
        const double d0 = H(0, 0);
        if (!(d0 > pivot)) break;
        const double l10 = H(1, 0) / d0, l20 = H(2, 0) / d0;
        const double d1 = H(1, 1) - l10 * H(1, 0);
        if (!(d1 > pivot)) break;
        const double l21 = (H(2, 1) - l20 * H(1, 0)) / d1;
        const double d2 = H(2, 2) - l20 * H(2, 0) - l21 * l21 * d1;
        if (!(d2 > pivot)) break;
        const double y0 = g[0], y1 = g[1] - l10 * y0, y2 = g[2] - l20 * y0 - l21 * y1;
        const double v2 = y2 / d2, v1 = y1 / d1 - l21 * v2, v0 = y0 / d0 - l10 * v1 - l20 * v2;
        const double v_squared = v0 * v0 + v1 * v1 + v2 * v2;
        q = multiply(q, Vec4(1.0, v0, v1, v2) / std::sqrt(1.0 + v_squared));
        if (v_squared < kLastStep2) return q;
    }
    // In the frame of q, so that a degenerate M keeps q (ties go to e_0).
    const Vec4 step = largest_eigenvector(horn_matrix(rotation_of(q).transpose() * M));
    return multiply(q, step).normalized();
}

Mat<3> fit_rotation_3(const Mat<3>& M, const Mat<3>* hint) {
    if (!M.allFinite()) return Mat<3>::Identity();
    const bool warm = hint && hint->allFinite() && hint->squaredNorm() > 0.0;
    return rotation_of(fit_quaternion(M, start_quaternion(warm ? *hint : M)));
}

Mat<2> fit_rotation_2(const Mat<2>& M, const Mat<2>* hint) {
    if (!M.allFinite()) return Mat<2>::Identity();
    // tr(R^T M) = c (M_00 + M_11) + s (M_10 - M_01) for R = [c -s; s c].
    const double c = M(0, 0) + M(1, 1), s = M(1, 0) - M(0, 1);
    const double r = std::hypot(c, s);
    if (!(r > 0.0)) {  // every rotation is a maximizer
        if (hint && hint->allFinite() && hint->squaredNorm() > 0.0)
            return fit_rotation_2(*hint, nullptr);
        return Mat<2>::Identity();
    }
    Mat<2> R;
    R << c / r, -s / r, s / r, c / r;
    return R;
}

}  // namespace

template <int D>
Mat<D> fit_rotation(const Mat<D>& M) {
    if constexpr (D == 2) {
        return fit_rotation_2(M, nullptr);
    } else {
        return fit_rotation_3(M, nullptr);
    }
}

template <int D>
Mat<D> fit_rotation(const Mat<D>& M, const Mat<D>& hint) {
    if constexpr (D == 2) {
        return fit_rotation_2(M, &hint);
    } else {
        return fit_rotation_3(M, &hint);
    }
}

template Mat<2> fit_rotation<2>(const Mat<2>&);
template Mat<3> fit_rotation<3>(const Mat<3>&);
template Mat<2> fit_rotation<2>(const Mat<2>&, const Mat<2>&);
template Mat<3> fit_rotation<3>(const Mat<3>&, const Mat<3>&);

}  // namespace sa
