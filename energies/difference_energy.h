#pragma once
// E_m of deformation posing (the paper's 5.4): the distance of each linear part to its
// reference,
//     E_m(A_i) = w_i |A_i - A_i^0|_F^2,
// with A_i^0 the start's linear part of simplex i (the ARAP deformation, before the disassembly
// projects it) and w_i its weight (the paper: mu for every simplex, unit weights; the mapping
// application's built-in difference weighs by the rest volume instead, energies/simplex_energy.h).
// A quadratic with Hessian 2 w_i I: convex (never projected) and finite everywhere (it bounds
// nothing: the barriers keep A_i feasible).

#include <utility>
#include <vector>

#include "optim/errors.h"
#include "optim/types.h"

namespace sa {

template <int D>
class DifferenceEnergy {
  public:
    static constexpr int arity = D * D;
    static constexpr bool is_convex = true;  // never projected

    /// `references` holds A_i^0 per simplex (in the simplex's rest frame, as the engine's A_i);
    /// `weights` one w_i >= 0 per simplex, or a single weight for all.
    DifferenceEnergy(std::vector<Mat<D>> references, std::vector<double> weights)
        : references_(std::move(references)), weights_(std::move(weights)) {
        if (weights_.size() != 1 && weights_.size() != references_.size()) {
            throw InvalidArgumentError("DifferenceEnergy: " + std::to_string(weights_.size()) +
                                       " weights for " + std::to_string(references_.size()) +
                                       " simplices (expected one or one per simplex)");
        }
        for (double w : weights_) {
            if (!(w >= 0.0 && w < kInfinity))
                throw InvalidArgumentError("DifferenceEnergy: a weight must be finite and >= 0");
        }
    }

    Index num_elements() const { return Index(references_.size()); }

    double value(Index i, const Vec<arity>& a) const {
        return weight(i) * (a - reference(i)).squaredNorm();
    }

    double value_gradient_hessian(Index i, const Vec<arity>& a, Vec<arity>& gradient,
                                  Mat<arity>& hessian) const {
        const Vec<arity> difference = a - reference(i);
        gradient = 2.0 * weight(i) * difference;
        hessian = 2.0 * weight(i) * Mat<arity>::Identity();
        return weight(i) * difference.squaredNorm();
    }

  private:
    double weight(Index i) const { return weights_.size() == 1 ? weights_[0] : weights_[i]; }
    Eigen::Map<const Vec<arity>> reference(Index i) const {
        return Eigen::Map<const Vec<arity>>(references_[i].data());
    }

    std::vector<Mat<D>> references_;
    std::vector<double> weights_;
};

}  // namespace sa
