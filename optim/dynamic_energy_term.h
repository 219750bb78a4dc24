#pragma once
// DynamicEnergyTerm<E>: the Term (term.h) of a DynamicElementEnergy E, each element naming its
// own number of variables (RaggedElements). One compiled class serves fans, rings and stars of
// every size: an element's variables are gathered into per-task scratch, its gradient and
// Hessian are written straight into its slots (the energy sees them as dynamic-size views), and
// dense Hessians are projected by the one dynamic-size eigen-solver of hessian_projection.cpp.
// Problem::add_term() makes one.

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <functional>
#include <utility>
#include <vector>

#include "optim/detail/element_reductions.h"
#include "optim/dynamic_element_energy.h"
#include "optim/ragged_elements.h"
#include "optim/term.h"

namespace sa {

template <DynamicElementEnergy E>
class DynamicEnergyTerm final : public Term {
  public:
    /// B of the energy's Hessian blocks; 0 when each element's Hessian is dense.
    static constexpr int B = dynamic_hessian_block_of<E>();

    DynamicEnergyTerm(std::string name, E energy, RaggedElements elements, double weight)
        : Term(std::move(name), weight),
          energy_(std::move(energy)),
          elements_(std::move(elements)) {
        if constexpr (B == 0) {
            hessian_offsets_.resize(std::size_t(elements_.size()) + 1, 0);
            for (Index e = 0; e < elements_.size(); ++e) {
                const std::int64_t n = elements_.arity(e);
                hessian_offsets_[e + 1] = hessian_offsets_[e] + n * n;
            }
        }
    }

    const E& energy() const { return energy_; }
    const RaggedElements& elements() const { return elements_; }

    TermLayout layout() const override {
        TermLayout l;
        l.num_elements = elements_.size();
        l.variables = elements_.indices().data();
        l.offsets = elements_.offsets().data();
        l.hessian_offsets = B == 0 ? hessian_offsets_.data() : nullptr;
        l.arity = elements_.max_arity();
        l.block = B;
        return l;
    }
    bool is_quadratic() const override { return is_quadratic_energy<E>(); }
    bool is_convex() const override { return is_convex_energy<E>(); }
    bool has_max_step() const override { return DynamicHasMaxStep<E>; }

    double value(const Eigen::VectorXd& x) const override {
        return detail::sum_of_element_values(
            elements_.size(), kGrain, [&] { return Scratch(elements_.max_arity()); },
            [&](Index e, Scratch& scratch) {
                return energy_.value(e, scratch.gather(x, elements_, e));
            });
    }

    double evaluate(const Eigen::VectorXd& x, double scale, double* gradient_slots,
                    double* hessian_slots) const override {
        const TermLayout l = layout();
        return tbb::parallel_deterministic_reduce(
            range(), 0.0,
            [&](const tbb::blocked_range<Index>& r, double acc) {
                Scratch scratch(elements_.max_arity());
                // A Hessian to drop when the caller wants none and the energy has no
                // value_gradient(): as large as the largest element's.
                std::vector<double> unused;
                if (hessian_slots == nullptr && !DynamicHasValueGradient<E>) {
                    const std::int64_t n = elements_.max_arity();
                    unused.resize(std::size_t(n * (B > 0 ? B : n)));
                }
                for (Index e = r.begin(); e != r.end(); ++e) {
                    const int n = elements_.arity(e), rows = B > 0 ? B : n;
                    const auto xe = scratch.gather(x, elements_, e);
                    Eigen::Map<Eigen::VectorXd> g(gradient_slots + l.begin(e), n);
                    double* h_data = hessian_slots != nullptr ? hessian_slots + l.hessian_begin(e)
                                                              : unused.data();
                    Eigen::Map<Eigen::MatrixXd> h(h_data, rows, n);
                    double v;
                    if constexpr (DynamicHasValueGradient<E>) {
                        v = hessian_slots == nullptr ? energy_.value_gradient(e, xe, g)
                                                     : energy_.value_gradient_hessian(e, xe, g, h);
                    } else {
                        v = energy_.value_gradient_hessian(e, xe, g, h);
                    }
                    acc += v;
                    g *= scale;
                    if (hessian_slots != nullptr) h *= scale;
                }
                return acc;
            },
            std::plus<double>());
    }

    Index project(const Eigen::VectorXd& x, double* hessian_slots, ProjectionMode mode,
                  double epsilon) const override {
        if constexpr (is_convex_energy<E>()) {
            return 0;
        } else {
            if (mode == ProjectionMode::kNone) return 0;
            const TermLayout l = layout();
            return tbb::parallel_deterministic_reduce(
                range(), Index{0},
                [&](const tbb::blocked_range<Index>& r, Index changed) {
                    Scratch scratch(elements_.max_arity());
                    for (Index e = r.begin(); e != r.end(); ++e) {
                        const int n = elements_.arity(e), rows = B > 0 ? B : n;
                        Eigen::Map<Eigen::MatrixXd> h(hessian_slots + l.hessian_begin(e), rows, n);
                        bool did = false;
                        if constexpr (DynamicHasOwnProjection<E>) {
                            did = energy_.project_hessian(e, scratch.gather(x, elements_, e), h,
                                                          mode, epsilon);
                        } else if constexpr (B > 0) {
                            for (int k = 0; k < n / B; ++k) {
                                Mat<B> block = h.middleCols(B * k, B);
                                if (project_hessian_block<B>(block, mode, epsilon)) {
                                    h.middleCols(B * k, B) = block;
                                    did = true;
                                }
                            }
                        } else {
                            did = project_hessian_block(MatrixRef(h), mode, epsilon);
                        }
                        changed += did;
                    }
                    return changed;
                },
                std::plus<Index>());
        }
    }

    double max_step(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) const override {
        if constexpr (!DynamicHasMaxStep<E>) {
            return kInfinity;
        } else {
            // Two scratches per task: the element's x and its dx.
            const auto make_scratch = [&] {
                return std::pair(Scratch(elements_.max_arity()), Scratch(elements_.max_arity()));
            };
            return detail::smallest_element_step(
                elements_.size(), kGrain, make_scratch,
                [&](Index e, std::pair<Scratch, Scratch>& at_along) {
                    return energy_.max_step(e, at_along.first.gather(x, elements_, e),
                                            at_along.second.gather(dx, elements_, e));
                });
        }
    }

    double element_value(Index e, const Eigen::VectorXd& x) const override {
        Scratch scratch(elements_.arity(e));
        return energy_.value(e, scratch.gather(x, elements_, e));
    }

  private:
    /// One task's room for an element's variables.
    struct Scratch {
        explicit Scratch(int capacity) : values(std::size_t(capacity)) {}
        Eigen::Map<const Eigen::VectorXd> gather(const Eigen::VectorXd& x,
                                                 const RaggedElements& elements, Index e) {
            const std::span<const Index> vars = elements[e];
            for (std::size_t k = 0; k < vars.size(); ++k) values[k] = x[vars[k]];
            return Eigen::Map<const Eigen::VectorXd>(values.data(), Eigen::Index(vars.size()));
        }
        std::vector<double> values;
    };

    tbb::blocked_range<Index> range() const {
        return tbb::blocked_range<Index>(0, elements_.size(), kGrain);
    }

    E energy_;
    RaggedElements elements_;
    std::vector<std::int64_t> hessian_offsets_;  ///< dense Hessians (B == 0) only
};

}  // namespace sa
