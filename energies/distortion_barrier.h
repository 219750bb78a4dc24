#pragma once
// Per-simplex energies of A built from a distortion d(A) that the user writes once, templated on
// the scalar type (double for values, Dual<D*D> for derivatives, as with AutodiffEnergy):
//
//   struct MyDistortion {                                   // D = 3
//       template <class T> T operator()(const Eigen::Matrix<T, 3, 3>& A) const { ... }
//       static constexpr bool rotation_invariant = true;    // optional: d(P A Q) = d(A) for
//   };                                                      // rotations P, Q
//
//   DistortionBarrier<D, F>   E_C of section 4.1.2 on d: e^{s d} / (K - d) for a bound K, e^{s d}
//                             without one; +inf when det A <= 0 or d >= K. Several barriers with
//                             their own bounds may be added at once (a conformal and a volumetric
//                             bound together). max_step: the root of det(A + t dA) in closed form
//                             (orientation_step.h); the bound is kept by the line search, which
//                             rejects +inf trial points. distortion() and with_bound() serve the
//                             verification and the optimal-bound rounds.
//   DistortionEnergy<D, F>    E_m = w_i d(A_i) with a weight per simplex (mu times the rest volume,
//                             typically).
//
// Derivatives come from Dual<D*D> (exact). The Hessian is projected through the singular vectors
// of A (rotation_invariant_projection.h) when F declares rotation_invariant, by the eigenvalues of
// the D^2 x D^2 block otherwise. BuiltinDistortion<D> is the functor of distortion.h's closed
// forms, so that a built-in distortion and a user's take the same path here (the mapping
// application's default SimplexEnergy keeps its own faster chain rule).

#include <cmath>
#include <vector>

#include "energies/barrier.h"
#include "energies/distortion.h"
#include "energies/orientation_step.h"
#include "energies/rotation_invariant_projection.h"
#include "optim/dual.h"
#include "optim/errors.h"

namespace sa {

template <class F>
constexpr bool is_rotation_invariant_distortion() {
    if constexpr (requires { F::rotation_invariant; }) {
        return F::rotation_invariant;
    } else {
        return false;
    }
}

/// The distortions of distortion.h that need no singular values, as a functor over any scalar.
template <int D>
struct BuiltinDistortion {
    static constexpr bool rotation_invariant = true;
    DistortionType type = DistortionType::kConformal;
    double gamma = 0.5;

    /// Throws InvalidArgumentError for kDifference and the distortions that need the sum of
    /// singular values (asap, arap, lscm).
    explicit BuiltinDistortion(DistortionType t, double g = 0.5) : type(t), gamma(g) {
        if (t == DistortionType::kDifference || needs_sigma_sum(t)) {
            throw InvalidArgumentError("BuiltinDistortion: " + to_string(t) +
                                       " is not a function of |A|, |cof A| and det A");
        }
    }

    template <class T>
    T operator()(const Eigen::Matrix<T, D, D>& A) const {
        MatrixInvariants<T> m;
        m.I1 = A.squaredNorm();
        m.J = A.determinant();
        if constexpr (D == 2) {
            m.I2 = m.J * m.J;
        } else {
            m.I2 = T(0.0);
            for (int k = 0; k < 3; ++k) {  // |cof A|^2: the cross products of column pairs
                const Eigen::Matrix<T, 3, 1> a = A.col((k + 1) % 3), b = A.col((k + 2) % 3);
                const Eigen::Matrix<T, 3, 1> c(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                               a[0] * b[1] - a[1] * b[0]);
                m.I2 += c.squaredNorm();
            }
        }
        m.sigma_sum = T(0.0);
        return distortion<D>(type, m, gamma);
    }
};

namespace detail {

/// A as a D x D matrix of Dual<D*D>, seeded with the identity: derivatives are in vec(A).
template <int D>
Eigen::Matrix<Dual<D * D>, D, D> dual_matrix(const Vec<D * D>& a) {
    Eigen::Matrix<Dual<D * D>, D, D> A;
    for (int j = 0; j < D; ++j)
        for (int i = 0; i < D; ++i) A(i, j) = Dual<D * D>::variable(a[i + D * j], i + D * j);
    return A;
}

template <int D, class F>
bool project_distortion_hessian(const Vec<D * D>& a, Mat<D * D>& h, ProjectionMode mode,
                                double epsilon) {
    if constexpr (is_rotation_invariant_distortion<F>()) {
        return project_rotation_invariant_hessian<D>(Eigen::Map<const Mat<D>>(a.data()), h, mode,
                                                     epsilon);
    } else {
        return project_hessian_block<D * D>(h, mode, epsilon);
    }
}

}  // namespace detail

template <int D, class F>
class DistortionBarrier {
  public:
    static constexpr int arity = D * D;

    explicit DistortionBarrier(F distortion, BarrierOptions options = {})
        : distortion_(std::move(distortion)), options_(options) {
        if (!(options_.bound > 0.0)) {
            throw InvalidArgumentError(
                "DistortionBarrier: bound = " + std::to_string(options_.bound) + ": must be > 0");
        }
        if (!(options_.s > 0.0) || !std::isfinite(options_.s))
            throw InvalidArgumentError("DistortionBarrier: s must be finite and > 0");
    }

    /// d(A), +inf when det A <= 0.
    double distortion(const Mat<D>& A) const {
        return A.determinant() > 0.0 ? double(distortion_(Mat<D>(A))) : kInfinity;
    }
    double bound() const { return options_.bound; }
    /// The same barrier with bound K.
    DistortionBarrier with_bound(double K) const {
        BarrierOptions o = options_;
        o.bound = K;
        return DistortionBarrier(distortion_, o);
    }
    /// s of e^{s d}.
    double exponent() const { return options_.s; }
    /// The same barrier with exponent scale s (> 0).
    DistortionBarrier with_exponent(double s) const {
        BarrierOptions o = options_;
        o.s = s;
        return DistortionBarrier(distortion_, o);
    }
    const F& functor() const { return distortion_; }

    double value(Index, const Vec<arity>& a) const {
        const Mat<D> A = Eigen::Map<const Mat<D>>(a.data());
        if (!(A.determinant() > 0.0)) return kInfinity;
        const double d = distortion_(A);
        if (!(d < options_.bound)) return kInfinity;
        const double e = barrier(d, options_);
        return std::isfinite(e) ? e : kInfinity;
    }
    double value_gradient_hessian(Index, const Vec<arity>& a, Vec<arity>& g, Mat<arity>& h) const {
        if (!(Eigen::Map<const Mat<D>>(a.data()).determinant() > 0.0)) return kInfinity;
        const Dual<arity> d = distortion_(detail::dual_matrix<D>(a));
        if (!(d.value < options_.bound)) return kInfinity;
        const Dual<arity> e = barrier(d, options_);
        if (!std::isfinite(e.value)) return kInfinity;
        g = e.gradient;
        h = e.hessian;
        return e.value;
    }
    double max_step(Index, const Vec<arity>& a, const Vec<arity>& da) const {
        return orientation_step<D>(Eigen::Map<const Mat<D>>(a.data()),
                                   Eigen::Map<const Mat<D>>(da.data()));
    }
    bool project_hessian(Index, const Vec<arity>& a, Mat<arity>& h, ProjectionMode mode,
                         double epsilon) const {
        return detail::project_distortion_hessian<D, F>(a, h, mode, epsilon);
    }

  private:
    F distortion_;
    BarrierOptions options_;
};

template <int D, class F>
class DistortionEnergy {
  public:
    static constexpr int arity = D * D;

    /// `weights[i]` multiplies d(A_i).
    DistortionEnergy(F distortion, std::vector<double> weights)
        : distortion_(std::move(distortion)), weights_(std::move(weights)) {}

    double value(Index i, const Vec<arity>& a) const {
        const Mat<D> A = Eigen::Map<const Mat<D>>(a.data());
        const double e = weights_[i] * double(distortion_(A));
        return std::isfinite(e) ? e : kInfinity;
    }
    double value_gradient_hessian(Index i, const Vec<arity>& a, Vec<arity>& g,
                                  Mat<arity>& h) const {
        const Dual<arity> d = distortion_(detail::dual_matrix<D>(a));
        if (!std::isfinite(d.value)) return kInfinity;
        g = weights_[i] * d.gradient;
        h = weights_[i] * d.hessian;
        return weights_[i] * d.value;
    }
    bool project_hessian(Index, const Vec<arity>& a, Mat<arity>& h, ProjectionMode mode,
                         double epsilon) const {
        return detail::project_distortion_hessian<D, F>(a, h, mode, epsilon);
    }

  private:
    F distortion_;
    std::vector<double> weights_;
};

}  // namespace sa
