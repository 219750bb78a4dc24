#include "energies/untangling_energy.h"

#include <cmath>

#include "energies/matrix_invariants.h"
#include "energies/rotation_invariant_projection.h"
#include "optim/dual.h"

namespace sa {

Chi regularized_determinant(double J, double epsilon) {
    const double r = std::sqrt(epsilon * epsilon + J * J);
    // (J + r) / 2 loses every digit for J << -eps; eps^2 / (2 (r - J)) is the same number.
    const double value = J > 0.0 ? 0.5 * (J + r) : 0.5 * epsilon * epsilon / (r - J);
    return {value, value / r, 0.5 * epsilon * epsilon / (r * r * r)};
}

namespace {

/// f of the two invariants I1 = |A|^2 and J = det A (double or Dual<2>).
template <int D, class S>
S untangling_of_invariants(const S& I1, const S& J, const UntanglingParameters& p) {
    const Chi c = regularized_determinant(value_of(J), p.epsilon);
    S chi;
    if constexpr (std::is_same_v<S, double>) {
        chi = c.value;
    } else {
        chi = J.chain(c.value, c.first, c.second);
    }
    using std::pow;
    const S shape = D == 2 ? I1 / chi : I1 / pow(chi, 2.0 / 3.0);
    const S volume = (1.0 + J * J) / chi;
    return (1.0 - p.theta) * shape + p.theta * volume;
}

}  // namespace

template <int D>
double UntanglingEnergy<D>::value(Index i, const Vec<arity>& a) const {
    const Mat<D> A = unvec<D>(a);
    const double e = untangling_of_invariants<D>(A.squaredNorm(), A.determinant(), *parameters_);
    return weights_[i] * e;
}

template <int D>
double UntanglingEnergy<D>::value_gradient_hessian(Index i, const Vec<arity>& a,
                                                   Vec<arity>& gradient,
                                                   Mat<arity>& hessian) const {
    const Mat<D> A = unvec<D>(a);
    const MatrixInvariants<Dual<arity>> m = matrix_invariants_with_derivatives<D>(A, false);
    // Differentiated in (I1, J), then chained to vec(A): H = e_I1 H_I1 + e_J H_J + G E G^T.
    const Dual<2> e = untangling_of_invariants<D>(Dual<2>::variable(m.I1.value, 0),
                                                  Dual<2>::variable(m.J.value, 1), *parameters_);
    Eigen::Matrix<double, arity, 2> G;
    G.col(0) = m.I1.gradient;
    G.col(1) = m.J.gradient;
    const double w = weights_[i];
    gradient.noalias() = w * (G * e.gradient);
    hessian.noalias() = G * (w * e.hessian) * G.transpose();
    hessian += (w * e.gradient[0]) * m.I1.hessian + (w * e.gradient[1]) * m.J.hessian;
    return w * e.value;
}

template <int D>
bool UntanglingEnergy<D>::project_hessian(Index, const Vec<arity>& a, Mat<arity>& hessian,
                                          ProjectionMode mode, double epsilon) const {
    return project_rotation_invariant_hessian<D>(unvec<D>(a), hessian, mode, epsilon);
}

template class UntanglingEnergy<2>;
template class UntanglingEnergy<3>;

}  // namespace sa
