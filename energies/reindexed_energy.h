#pragma once
// An element energy on a selection of another one's elements: element k of ReindexedEnergy is
// element `selected[k]` of the inner energy. It is how a per-simplex energy written for a whole
// mesh (its rest data indexed by simplex) serves a part of it: a submesh, the simplices the
// vertex stage moves, or a subset given to the engine. Any ElementEnergy works, the user's as
// well as the built-in ones; every optional member (max_step, value_gradient, project_hessian,
// is_quadratic, is_convex) is forwarded when the inner energy has it.
//
// The inner energy is shared, not copied: restricting a million-simplex energy to many small
// regions costs one index list per region. Per call it adds one index load.

#include <memory>
#include <vector>

#include "optim/element_energy.h"

namespace sa {

template <ElementEnergy E>
class ReindexedEnergy {
  public:
    static constexpr int arity = E::arity;
    static constexpr bool is_quadratic = is_quadratic_energy<E>();
    static constexpr bool is_convex = is_convex_energy<E>();

    /// Element k is `inner`'s element selected[k].
    ReindexedEnergy(std::shared_ptr<const E> inner, std::vector<Index> selected)
        : inner_(std::move(inner)), selected_(std::move(selected)) {}

    double value(Index k, const Vec<arity>& x) const { return inner_->value(selected_[k], x); }
    double value_gradient_hessian(Index k, const Vec<arity>& x, Vec<arity>& g,
                                  Mat<arity>& h) const {
        return inner_->value_gradient_hessian(selected_[k], x, g, h);
    }
    double value_gradient(Index k, const Vec<arity>& x,
                          Vec<arity>& g) const requires HasValueGradient<E> {
        return inner_->value_gradient(selected_[k], x, g);
    }
    double max_step(Index k, const Vec<arity>& x,
                    const Vec<arity>& dx) const requires HasMaxStep<E> {
        return inner_->max_step(selected_[k], x, dx);
    }
    bool project_hessian(Index k, const Vec<arity>& x, Mat<arity>& h, ProjectionMode mode,
                         double epsilon) const requires HasOwnProjection<E> {
        return inner_->project_hessian(selected_[k], x, h, mode, epsilon);
    }

    const E& inner() const { return *inner_; }
    const std::shared_ptr<const E>& shared_inner() const { return inner_; }
    const std::vector<Index>& selected() const { return selected_; }
    Index size() const { return static_cast<Index>(selected_.size()); }

  private:
    std::shared_ptr<const E> inner_;
    std::vector<Index> selected_;
};

}  // namespace sa
