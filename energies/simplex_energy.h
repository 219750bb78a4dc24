#pragma once
// The per-simplex energy of Simplex Assembly (Eq. 10 without the assembly term):
//     mu * w_i * d_m(A_i) + E_C(A_i)
// over the D*D entries of A_i (vec(A_i), column-major). d_m is the mapping distortion (any
// DistortionType, or none: E_m = 0); E_C is the barrier of barrier.h on the conformal,
// volumetric or isometric distortion with bound K. The value is +inf when det A_i <= 0 or the
// barrier distortion reaches K.
//
// max_step() is exact for det A > 0 (a quadratic in 2D, a cubic in 3D), for the conformal bound
// in 2D (|A|^2 - 2 K det A, a quadratic) and for the volumetric bound (det A between
// K -+ sqrt(K^2 - 1)); the line search rejects +inf values for the other bounds.

#include <optional>
#include <vector>

#include "energies/barrier.h"
#include "energies/distortion.h"
#include "optim/hessian_projection.h"

namespace sa {

struct SimplexEnergyOptions {
    /// Distortion inside the barrier: conformal, volumetric or isometric.
    DistortionType barrier_distortion = DistortionType::kConformal;
    BarrierOptions barrier;
    /// d_m of E_m; none means E_m = 0.
    std::optional<DistortionType> mapping_distortion;
    /// mu, the weight of E_m (the paper's default 1000).
    double mu = 1000.0;
    /// gamma of the isometric distortion.
    double gamma = 0.5;

    /// Throws InvalidArgumentError naming the first bad field.
    void validate() const;
};

template <int D>
class SimplexEnergy {
  public:
    static constexpr int arity = D * D;

    /// `weights` holds w_i per simplex (its rest volume, typically); `references` holds A0_i per
    /// simplex, required when the mapping distortion is kDifference.
    SimplexEnergy(SimplexEnergyOptions options, std::vector<double> weights,
                  std::vector<Mat<D>> references = {});

    double value(Index i, const Vec<arity>& a) const;
    double value_gradient_hessian(Index i, const Vec<arity>& a, Vec<arity>& gradient,
                                  Mat<arity>& hessian) const;
    double max_step(Index i, const Vec<arity>& a, const Vec<arity>& da) const;
    /// Projects the Hessian at `a` in place through the singular vectors of A
    /// (rotation_invariant_projection.h: every barrier and mapping distortion here qualifies).
    bool project_hessian(Index i, const Vec<arity>& a, Mat<arity>& hessian, ProjectionMode mode,
                         double epsilon) const;

    /// The barrier distortion of A (+inf when det A <= 0).
    double barrier_distortion(const Mat<D>& A) const;
    const SimplexEnergyOptions& options() const { return options_; }

  private:
    SimplexEnergyOptions options_;
    std::vector<double> weights_;
    std::vector<Mat<D>> references_;
    bool sigma_sum_ = false;
};

extern template class SimplexEnergy<2>;
extern template class SimplexEnergy<3>;

}  // namespace sa
