#pragma once
// A regularized barrier whose minimizers are untangled maps (Garanzha, Kaporin, Kudryavtseva,
// Protais, Ray and Sokolov 2021, "Foldover-free maps in 50 lines of code"), per simplex of its
// linear part A (D x D, vec(A) column-major):
//     f_eps(A) = w ((1 - theta) |A|_F^2 / chi(det A, eps)^(2/D) + theta (1 + det(A)^2) / chi(det A,
//     eps)) chi(J, eps) = (J + sqrt(eps^2 + J^2)) / 2
// w is the simplex's weight (its rest volume). chi is a smooth, positive stand-in for det A: for
// eps > 0 the energy is finite everywhere, inverted simplices included, so Newton can start from
// any map; as eps -> 0, chi -> max(det A, 0) and f becomes the plain shape (|A|^2 / det^(2/D),
// conformal) plus volume ((1 + det^2) / det) distortion, infinite on inverted simplices. The
// driver lowers eps from one step to the next (UntanglingParameters) so that the minimizers of
// f_eps become untangled maps (frontends/simplex_assembly/untangle.h).
//
// Unlike E_C (barrier.h) there is no exponential: the energy grows like |A|^2 / det^(2/D), so
// simplices that the data force to extreme distortion (a fixed boundary with slivers) do not
// swamp the others.

#include <memory>
#include <vector>

#include "optim/hessian_projection.h"
#include "optim/types.h"

namespace sa {

/// Shared between the energy and the driver, which changes eps between Newton steps.
struct UntanglingParameters {
    double epsilon = 1.0;  ///< > 0
    double theta = 0.5;    ///< the weight of the volume term, in (0, 1)
};

/// chi(J, eps) and its first two derivatives in J, stable for J < 0 as well.
struct Chi {
    double value, first, second;
};
Chi regularized_determinant(double J, double epsilon);

template <int D>
class UntanglingEnergy {
  public:
    static constexpr int arity = D * D;

    UntanglingEnergy(std::vector<double> weights, std::shared_ptr<const UntanglingParameters> p)
        : weights_(std::move(weights)), parameters_(std::move(p)) {}

    double value(Index i, const Vec<arity>& a) const;
    double value_gradient_hessian(Index i, const Vec<arity>& a, Vec<arity>& gradient,
                                  Mat<arity>& hessian) const;
    /// Through the singular vectors of A when det A > 0 (f depends on |A| and det A only:
    /// rotation_invariant_projection.h), by the eigen-decomposition of the block otherwise.
    bool project_hessian(Index i, const Vec<arity>& a, Mat<arity>& hessian, ProjectionMode mode,
                         double epsilon) const;

  private:
    std::vector<double> weights_;
    std::shared_ptr<const UntanglingParameters> parameters_;
};

extern template class UntanglingEnergy<2>;
extern template class UntanglingEnergy<3>;

}  // namespace sa
