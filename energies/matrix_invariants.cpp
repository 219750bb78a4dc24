#include "energies/matrix_invariants.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>

namespace sa {

namespace {

Mat<3> cross_matrix(const Eigen::Vector3d& v) {
    Mat<3> m;
    m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return m;
}

/// Sum of singular values of a 3x3 A with det A > 0: gradient R = U V^T (the polar rotation),
/// Hessian sum_{i<j} 2 / (s_i + s_j) q_ij q_ij^T with q_ij = vec(U (e_i e_j^T - e_j e_i^T) V^T)
/// / sqrt(2) (the "twist" modes of Smith et al. 2019, Analytic Eigensystems for Isotropic
/// Distortion Energies).
Dual<9> sigma_sum_3d(const Mat<3>& A) {
    const Eigen::JacobiSVD<Mat<3>> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Mat<3> U = svd.matrixU(), V = svd.matrixV();
    Eigen::Vector3d s = svd.singularValues();
    if (U.determinant() * V.determinant() < 0.0) {  // det A < 0: keep R a rotation (signed SVD)
        U.col(2) *= -1.0;
        s[2] *= -1.0;
    }
    Dual<9> result;
    result.value = s.sum();
    const Mat<3> R = U * V.transpose();
    result.gradient = Eigen::Map<const Vec<9>>(R.data());
    const int pairs[3][2] = {{0, 1}, {1, 2}, {0, 2}};
    for (const auto& p : pairs) {
        const int i = p[0], j = p[1];
        const Mat<3> twist =
            (U.col(i) * V.col(j).transpose() - U.col(j) * V.col(i).transpose()) / std::sqrt(2.0);
        const Vec<9> q = Eigen::Map<const Vec<9>>(twist.data());
        result.hessian += (2.0 / (s[i] + s[j])) * q * q.transpose();
    }
    return result;
}

}  // namespace

template <>
MatrixInvariants<double> matrix_invariants<2>(const Mat<2>& A, bool with_sigma_sum) {
    MatrixInvariants<double> m;
    m.I1 = A.squaredNorm();
    m.J = A.determinant();
    m.I2 = m.J * m.J;
    m.sigma_sum = with_sigma_sum ? std::hypot(A(0, 0) + A(1, 1), A(1, 0) - A(0, 1)) : 0.0;
    return m;
}

template <>
MatrixInvariants<double> matrix_invariants<3>(const Mat<3>& A, bool with_sigma_sum) {
    MatrixInvariants<double> m;
    m.I1 = A.squaredNorm();
    m.J = A.determinant();
    const Eigen::Vector3d c0 = A.col(0), c1 = A.col(1), c2 = A.col(2);
    m.I2 = c1.cross(c2).squaredNorm() + c2.cross(c0).squaredNorm() + c0.cross(c1).squaredNorm();
    m.sigma_sum = 0.0;
    if (with_sigma_sum) {
        const Eigen::Vector3d s = Eigen::JacobiSVD<Mat<3>>(A).singularValues();
        m.sigma_sum = s[0] + s[1] + (m.J < 0.0 ? -s[2] : s[2]);
    }
    return m;
}

template <>
MatrixInvariants<Dual<4>> matrix_invariants_with_derivatives<2>(const Mat<2>& A,
                                                                bool with_sigma_sum) {
    const Vec<4> a = Eigen::Map<const Vec<4>>(A.data());
    MatrixInvariants<Dual<4>> m;
    m.I1 = Dual<4>(a.squaredNorm(), 2.0 * a, 2.0 * Mat<4>::Identity());
    Mat<4> hj = Mat<4>::Zero();
    hj(0, 3) = hj(3, 0) = 1.0;
    hj(1, 2) = hj(2, 1) = -1.0;
    m.J = Dual<4>(a[0] * a[3] - a[1] * a[2], Vec<4>(a[3], -a[2], -a[1], a[0]), hj);
    m.I2 = m.J * m.J;
    if (with_sigma_sum) {
        // sigma_1 + sigma_2 = |(A00 + A11, A10 - A01)| when det A >= 0.
        const auto x = Dual<4>::variables(a);
        const Dual<4> p = x[0] + x[3], q = x[1] - x[2];
        m.sigma_sum = sqrt(p * p + q * q);
    }
    return m;
}

template <>
MatrixInvariants<Dual<9>> matrix_invariants_with_derivatives<3>(const Mat<3>& A,
                                                                bool with_sigma_sum) {
    const Vec<9> a = Eigen::Map<const Vec<9>>(A.data());
    MatrixInvariants<Dual<9>> m;
    m.I1 = Dual<9>(a.squaredNorm(), 2.0 * a, 2.0 * Mat<9>::Identity());

    const Eigen::Vector3d c[3] = {A.col(0), A.col(1), A.col(2)};
    // J = c0 . (c1 x c2): d J / d c_k = c_{k+1} x c_{k+2}; d^2 J / d c_k d c_{k+1} = -[c_{k+2}]_x.
    m.J.value = A.determinant();
    m.J.hessian.setZero();
    for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        m.J.gradient.segment<3>(3 * k) = c[k1].cross(c[k2]);
        m.J.hessian.block<3, 3>(3 * k, 3 * k1) = -cross_matrix(c[k2]);
        m.J.hessian.block<3, 3>(3 * k1, 3 * k) = cross_matrix(c[k2]);
    }

    // I2 = sum over column pairs (p, q) of |c_p x c_q|^2 = |c_p|^2 |c_q|^2 - (c_p . c_q)^2.
    m.I2.value = 0.0;
    m.I2.gradient.setZero();
    m.I2.hessian.setZero();
    const Mat<3> I = Mat<3>::Identity();
    for (int p = 0; p < 3; ++p) {
        const int q = (p + 1) % 3;
        const Eigen::Vector3d& u = c[p];
        const Eigen::Vector3d& v = c[q];
        const double uu = u.squaredNorm(), vv = v.squaredNorm(), uv = u.dot(v);
        m.I2.value += uu * vv - uv * uv;
        m.I2.gradient.segment<3>(3 * p) += 2.0 * vv * u - 2.0 * uv * v;
        m.I2.gradient.segment<3>(3 * q) += 2.0 * uu * v - 2.0 * uv * u;
        m.I2.hessian.block<3, 3>(3 * p, 3 * p) += 2.0 * vv * I - 2.0 * v * v.transpose();
        m.I2.hessian.block<3, 3>(3 * q, 3 * q) += 2.0 * uu * I - 2.0 * u * u.transpose();
        const Mat<3> cross = 4.0 * u * v.transpose() - 2.0 * v * u.transpose() - 2.0 * uv * I;
        m.I2.hessian.block<3, 3>(3 * p, 3 * q) += cross;
        m.I2.hessian.block<3, 3>(3 * q, 3 * p) += cross.transpose();
    }
    if (with_sigma_sum) m.sigma_sum = sigma_sum_3d(A);
    return m;
}

}  // namespace sa
