#pragma once
// Distortions of a D x D linear part A (section 3 of the paper), each written once over the
// scalar type S (double for values, Dual<D*D> for derivatives) from MatrixInvariants. sigma_k are
// the singular values of A; every distortion below is evaluated for det A > 0.
//
//   conformal           2D: |A|_F^2 / (2 det A) = (s1/s2 + s2/s1) / 2
//                       3D: (|A|_F^2 |A^-1|_F^2 - 1) / 8
//                       (1 at a similarity: the paper's general 1/2^d must read 1/2^(d(d-1)/2))
//   volumetric          (det A + 1 / det A) / 2
//   isometric           gamma * conformal + (1 - gamma) * volumetric   (gamma = 0.5 by default)
//   dirichlet           sum_k s_k^2 = |A|_F^2
//   symmetric-dirichlet |A|_F^2 + |A^-1|_F^2
//   green-lagrange      sum_k (s_k^2 - 1)^2 = |A^T A - I|_F^2
//   asap                sum_{j != k} (s_j - s_k)^2   (as-similar-as-possible)
//   arap                sum_k (s_k - 1)^2            (as-rigid-as-possible)
//   lscm                2D: (s1 - s2)^2 = |A|_F^2 - 2 det A, the least-squares conformal energy;
//                       3D: half the asap energy
//   difference          |A - A0|_F^2 for a given A0 per simplex (not a function of A alone: see
//                       difference_distortion)

#include <optional>
#include <string>
#include <vector>

#include "energies/matrix_invariants.h"

namespace sa {

enum class DistortionType {
    kConformal,
    kVolumetric,
    kIsometric,
    kDirichlet,
    kSymmetricDirichlet,
    kGreenLagrange,
    kAsap,
    kArap,
    kLscm,
    kDifference,
};

std::string to_string(DistortionType type);
/// Parses the names above ("conformal", "symmetric-dirichlet", ...); throws InvalidArgumentError
/// listing the accepted names otherwise.
DistortionType parse_distortion(const std::string& name);
const std::vector<DistortionType>& all_distortions();

/// True when the distortion needs the sum of singular values (an SVD in 3D).
inline bool needs_sigma_sum(DistortionType type) {
    return type == DistortionType::kAsap || type == DistortionType::kArap ||
           type == DistortionType::kLscm;
}

/// The distortion `type` of A given its invariants. Not for kDifference.
template <int D, class S>
S distortion(DistortionType type, const MatrixInvariants<S>& m, double gamma = 0.5) {
    const S& I1 = m.I1;
    const S& J = m.J;
    auto inverse_norm2 = [&] { return (D == 2 ? I1 : m.I2) / (J * J); };  // |A^-1|_F^2
    auto conformal = [&]() -> S {
        if constexpr (D == 2) {
            return I1 / (2.0 * J);
        } else {
            return (I1 * inverse_norm2() - 1.0) / 8.0;
        }
    };
    auto volumetric = [&]() -> S { return 0.5 * (J + 1.0 / J); };
    auto asap = [&]() -> S { return 2.0 * (double(D) * I1 - m.sigma_sum * m.sigma_sum); };
    switch (type) {
        case DistortionType::kConformal:
            return conformal();
        case DistortionType::kVolumetric:
            return volumetric();
        case DistortionType::kIsometric:
            return gamma * conformal() + (1.0 - gamma) * volumetric();
        case DistortionType::kDirichlet:
            return I1;
        case DistortionType::kSymmetricDirichlet:
            return I1 + inverse_norm2();
        case DistortionType::kGreenLagrange:
            // sum s^4 = I1^2 - 2 I2; so sum (s^2 - 1)^2 = I1^2 - 2 I2 - 2 I1 + D.
            return I1 * I1 - 2.0 * m.I2 - 2.0 * I1 + double(D);
        case DistortionType::kAsap:
            return asap();
        case DistortionType::kArap:
            return I1 - 2.0 * m.sigma_sum + double(D);
        case DistortionType::kLscm:
            return 0.5 * asap();
        case DistortionType::kDifference:
            break;
    }
    return S(kInfinity);
}

/// |A - A0|_F^2 with its derivatives with respect to vec(A).
template <int D>
Dual<D * D> difference_distortion(const Mat<D>& A, const Mat<D>& A0) {
    constexpr int N = D * D;
    const Mat<D> diff = A - A0;
    const Vec<N> d = Eigen::Map<const Vec<N>>(diff.data());
    return Dual<N>(d.squaredNorm(), 2.0 * d, 2.0 * Mat<N>::Identity());
}

}  // namespace sa
