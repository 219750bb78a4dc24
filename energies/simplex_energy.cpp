#include "energies/simplex_energy.h"

#include <cmath>
#include <sstream>
#include <type_traits>

#include "energies/orientation_step.h"
#include "energies/rotation_invariant_projection.h"
#include "optim/errors.h"

namespace sa {

void SimplexEnergyOptions::validate() const {
    auto fail = [](const std::string& field, double value, const std::string& rule) {
        std::ostringstream msg;
        msg << "SimplexEnergyOptions." << field << " = " << value << ": " << rule;
        throw InvalidArgumentError(msg.str());
    };
    if (barrier_distortion != DistortionType::kConformal &&
        barrier_distortion != DistortionType::kVolumetric &&
        barrier_distortion != DistortionType::kIsometric) {
        throw InvalidArgumentError(
            "SimplexEnergyOptions.barrier_distortion = " + to_string(barrier_distortion) +
            ": must be conformal, volumetric or isometric");
    }
    if (!(barrier.bound > 1.0)) fail("barrier.bound", barrier.bound, "must be > 1 (or infinite)");
    if (!(barrier.s > 0.0) || !std::isfinite(barrier.s))
        fail("barrier.s", barrier.s, "must be > 0");
    if (!(mu >= 0.0) || !std::isfinite(mu)) fail("mu", mu, "must be finite and >= 0");
    if (!(gamma >= 0.0 && gamma <= 1.0)) fail("gamma", gamma, "must be in [0, 1]");
}

template <int D>
SimplexEnergy<D>::SimplexEnergy(SimplexEnergyOptions options, std::vector<double> weights,
                                std::vector<Mat<D>> references)
    : options_(std::move(options)),
      weights_(std::move(weights)),
      references_(std::move(references)) {
    options_.validate();
    if (options_.mapping_distortion == DistortionType::kDifference &&
        references_.size() != weights_.size()) {
        throw InvalidArgumentError(
            "SimplexEnergy: the difference distortion needs one reference "
            "matrix per simplex (" +
            std::to_string(weights_.size()) + " simplices, " + std::to_string(references_.size()) +
            " references)");
    }
    sigma_sum_ = options_.mapping_distortion && needs_sigma_sum(*options_.mapping_distortion);
}

template <int D>
double SimplexEnergy<D>::barrier_distortion(const Mat<D>& A) const {
    const MatrixInvariants<double> m = matrix_invariants<D>(A, false);
    if (!(m.J > 0.0)) return kInfinity;
    return distortion<D>(options_.barrier_distortion, m, options_.gamma);
}

template <int D>
double SimplexEnergy<D>::value(Index i, const Vec<arity>& a) const {
    const Mat<D> A = unvec<D>(a);
    const MatrixInvariants<double> m = matrix_invariants<D>(A, sigma_sum_);
    if (!(m.J > 0.0)) return kInfinity;
    const double d = distortion<D>(options_.barrier_distortion, m, options_.gamma);
    if (!(d < options_.barrier.bound)) return kInfinity;
    double e = barrier(d, options_.barrier);
    if (options_.mapping_distortion) {
        const DistortionType type = *options_.mapping_distortion;
        const double dm = type == DistortionType::kDifference
                              ? (A - references_[i]).squaredNorm()
                              : distortion<D>(type, m, options_.gamma);
        e += options_.mu * weights_[i] * dm;
    }
    return std::isfinite(e) ? e : kInfinity;
}

template <int D>
double SimplexEnergy<D>::value_gradient_hessian(Index i, const Vec<arity>& a, Vec<arity>& gradient,
                                                Mat<arity>& hessian) const {
    const Mat<D> A = unvec<D>(a);
    const MatrixInvariants<Dual<arity>> m = matrix_invariants_with_derivatives<D>(A, sigma_sum_);
    if (!(m.J.value > 0.0)) return kInfinity;
    const bool difference =
        options_.mapping_distortion && *options_.mapping_distortion == DistortionType::kDifference;
    // The energy of the invariants (barrier, then the mapping distortion unless it is the
    // difference to a reference, which is not a function of them); +inf beyond the bound.
    auto energy_of = [&](const auto& invariants) {
        using S = std::decay_t<decltype(invariants.J)>;
        const S d = distortion<D>(options_.barrier_distortion, invariants, options_.gamma);
        if (!(d.value < options_.barrier.bound)) return S(kInfinity);
        S e = barrier(d, options_.barrier);
        if (options_.mapping_distortion && !difference) {
            e += (options_.mu * weights_[i]) *
                 distortion<D>(*options_.mapping_distortion, invariants, options_.gamma);
        }
        return e;
    };
    double value = 0.0;
    if constexpr (D == 2) {
        // Four invariants for four variables: nothing to gain from the chain below.
        const Dual<arity> e = energy_of(m);
        value = e.value;
        gradient = e.gradient;
        hessian = e.hessian;
    } else {
        // Differentiated in the four invariants (Dual<4>), then chained to vec(A) once:
        // H = sum_k e_k H_k + G E G^T with G = [grad I1, grad I2, grad J, grad S]. Differentiating
        // every operation in vec(A) (Dual<9>) updated a 9 x 9 Hessian per operation, about twice
        // the evaluation time (docs/measurements.md, "Figures moved out of the code").
        auto seeded = [](double x, int k) {
            Dual<4> v(x);
            v.gradient[k] = 1.0;
            return v;
        };
        const Dual<4> e = energy_of(
            MatrixInvariants<Dual<4>>{seeded(m.I1.value, 0), seeded(m.I2.value, 1),
                                      seeded(m.J.value, 2), seeded(m.sigma_sum.value, 3)});
        const Dual<arity>* invariant[4] = {&m.I1, &m.I2, &m.J, &m.sigma_sum};
        Eigen::Matrix<double, arity, 4> G;
        for (int k = 0; k < 4; ++k) G.col(k) = invariant[k]->gradient;
        value = e.value;
        gradient.noalias() = G * e.gradient;
        hessian.noalias() = G * e.hessian * G.transpose();
        for (int k = 0; k < 4; ++k) {
            if (e.gradient[k] != 0.0) hessian += e.gradient[k] * invariant[k]->hessian;
        }
    }
    if (!(value < kInfinity)) return kInfinity;
    if (difference) {
        const Dual<arity> dm = difference_distortion<D>(A, references_[i]);
        const double w = options_.mu * weights_[i];
        value += w * dm.value;
        gradient += w * dm.gradient;
        hessian += w * dm.hessian;
    }
    return std::isfinite(value) ? value : kInfinity;
}

template <int D>
bool SimplexEnergy<D>::project_hessian(Index, const Vec<arity>& a, Mat<arity>& hessian,
                                       ProjectionMode mode, double epsilon) const {
    return project_rotation_invariant_hessian<D>(unvec<D>(a), hessian, mode, epsilon);
}

template <int D>
double SimplexEnergy<D>::max_step(Index, const Vec<arity>& a, const Vec<arity>& da) const {
    const Mat<D> A = unvec<D>(a), B = unvec<D>(da);
    const auto det = determinant_polynomial<D>(A, B);
    double step = smallest_positive_root(det[0], det[1], det[2], det[3]);
    const double K = options_.barrier.bound;
    if (K < kInfinity) {
        if (options_.barrier_distortion == DistortionType::kConformal && D == 2) {
            // |A + tB|^2 - 2 K det(A + tB) reaches 0 where the conformal distortion reaches K.
            const double c0 = A.squaredNorm() - 2.0 * K * det[0];
            const double c1 = 2.0 * A.cwiseProduct(B).sum() - 2.0 * K * det[1];
            const double c2 = B.squaredNorm() - 2.0 * K * det[2];
            step = std::min(step, smallest_positive_root(c0, c1, c2));
        } else if (options_.barrier_distortion == DistortionType::kVolumetric) {
            // (J + 1/J) / 2 < K  <=>  K - sqrt(K^2 - 1) < J < K + sqrt(K^2 - 1).
            const double r = std::sqrt(K * K - 1.0);
            for (double threshold : {K - r, K + r}) {
                step = std::min(step,
                                smallest_positive_root(det[0] - threshold, det[1], det[2], det[3]));
            }
        }
    }
    return step;
}

template class SimplexEnergy<2>;
template class SimplexEnergy<3>;

}  // namespace sa
