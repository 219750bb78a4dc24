#pragma once
// EnergyTerm<E>: the Term (term.h) of an ElementEnergy E of fixed arity N, every element naming N
// variables; the per-element calls are inlined and the element's blocks are fixed-size.
// Problem::add_term() makes one.

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <array>
#include <functional>
#include <vector>

#include "optim/detail/element_reductions.h"
#include "optim/element_energy.h"
#include "optim/term.h"

namespace sa {

template <ElementEnergy E>
class EnergyTerm final : public Term {
  public:
    static constexpr int N = E::arity;
    static constexpr int B = hessian_block_of<E>();
    using Element = std::array<Index, N>;

    EnergyTerm(std::string name, E energy, std::vector<Element> elements, double weight)
        : Term(std::move(name), weight),
          energy_(std::move(energy)),
          elements_(std::move(elements)) {}

    const E& energy() const { return energy_; }
    const std::vector<Element>& elements() const { return elements_; }

    TermLayout layout() const override {
        static_assert(sizeof(Element) == N * sizeof(Index), "elements are stored back to back");
        TermLayout l;
        l.num_elements = static_cast<Index>(elements_.size());
        l.variables = elements_.empty() ? nullptr : elements_.front().data();
        l.arity = N;
        l.block = B;
        return l;
    }
    bool is_quadratic() const override { return is_quadratic_energy<E>(); }
    bool is_convex() const override { return is_convex_energy<E>(); }
    bool has_max_step() const override { return HasMaxStep<E>; }

    double value(const Eigen::VectorXd& x) const override {
        return detail::sum_of_element_values(
            static_cast<Index>(elements_.size()), kGrain, [] { return 0; },
            [&](Index e, int) { return energy_.value(e, gather(x, e)); });
    }

    double evaluate(const Eigen::VectorXd& x, double scale, double* gradient_slots,
                    double* hessian_slots) const override {
        return tbb::parallel_deterministic_reduce(
            range(), 0.0,
            [&](const tbb::blocked_range<Index>& r, double acc) {
                Vec<N> g;
                Mat<N> h;
                for (Index e = r.begin(); e != r.end(); ++e) {
                    const Vec<N> xe = gather(x, e);
                    double v;
                    if constexpr (HasValueGradient<E>) {
                        v = hessian_slots == nullptr ? energy_.value_gradient(e, xe, g)
                                                     : energy_.value_gradient_hessian(e, xe, g, h);
                    } else {
                        v = energy_.value_gradient_hessian(e, xe, g, h);
                    }
                    acc += v;
                    Eigen::Map<Vec<N>>(gradient_slots + std::size_t(e) * N) = scale * g;
                    if (hessian_slots != nullptr) store_blocks(h, scale, hessian_slots, e);
                }
                return acc;
            },
            std::plus<double>());
    }

    Index project(const Eigen::VectorXd& x, double* hessian_slots, ProjectionMode mode,
                  double epsilon) const override {
        // A convex energy's blocks are positive semidefinite already: the Hessian assembler never
        // projects them, and no eigen-solver of their arity need be compiled.
        if constexpr (is_convex_energy<E>()) {
            return 0;
        } else {
            return project_elements(x, hessian_slots, mode, epsilon);
        }
    }

    double max_step(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) const override {
        if constexpr (!HasMaxStep<E>) {
            return kInfinity;
        } else {
            return detail::smallest_element_step(
                static_cast<Index>(elements_.size()), kGrain, [] { return 0; },
                [&](Index e, int) { return energy_.max_step(e, gather(x, e), gather(dx, e)); });
        }
    }

    double element_value(Index e, const Eigen::VectorXd& x) const override {
        return energy_.value(e, gather(x, e));
    }

  private:
    Index project_elements(const Eigen::VectorXd& x, double* hessian_slots, ProjectionMode mode,
                           double epsilon) const {
        if (mode == ProjectionMode::kNone) return 0;
        return tbb::parallel_deterministic_reduce(
            range(), Index{0},
            [&](const tbb::blocked_range<Index>& r, Index changed) {
                for (Index e = r.begin(); e != r.end(); ++e) {
                    bool did = false;
                    if constexpr (B == N) {
                        Eigen::Map<Mat<N>> slot(hessian_slots + std::size_t(e) * N * N);
                        Mat<N> h = slot;
                        if constexpr (HasOwnProjection<E>) {
                            did = energy_.project_hessian(e, gather(x, e), h, mode, epsilon);
                        } else {
                            did = project_hessian_block<N>(h, mode, epsilon);
                        }
                        if (did) slot = h;
                    } else if constexpr (HasOwnProjection<E>) {
                        Mat<N> h = Mat<N>::Zero();
                        for (int k = 0; k < N / B; ++k)
                            h.template block<B, B>(B * k, B * k) = block_slot(hessian_slots, e, k);
                        did = energy_.project_hessian(e, gather(x, e), h, mode, epsilon);
                        if (did) store_blocks(h, 1.0, hessian_slots, e);
                    } else {
                        for (int k = 0; k < N / B; ++k) {
                            Mat<B> h = block_slot(hessian_slots, e, k);
                            if (project_hessian_block<B>(h, mode, epsilon)) {
                                block_slot(hessian_slots, e, k) = h;
                                did = true;
                            }
                        }
                    }
                    changed += did;
                }
                return changed;
            },
            std::plus<Index>());
    }

    /// Block k of element e's Hessian slots.
    static Eigen::Map<Mat<B>> block_slot(double* hessian_slots, Index e, int k) {
        return Eigen::Map<Mat<B>>(hessian_slots + std::size_t(e) * N * B + std::size_t(k) * B * B);
    }
    /// scale times the diagonal blocks of h into element e's slots.
    static void store_blocks(const Mat<N>& h, double scale, double* hessian_slots, Index e) {
        if constexpr (B == N) {
            Eigen::Map<Mat<N>>(hessian_slots + std::size_t(e) * N * N) = scale * h;
        } else {
            for (int k = 0; k < N / B; ++k)
                block_slot(hessian_slots, e, k) = scale * h.template block<B, B>(B * k, B * k);
        }
    }
    tbb::blocked_range<Index> range() const {
        return tbb::blocked_range<Index>(0, static_cast<Index>(elements_.size()), kGrain);
    }
    Vec<N> gather(const Eigen::VectorXd& x, Index e) const {
        Vec<N> xe;
        const Element& vars = elements_[e];
        for (int k = 0; k < N; ++k) xe[k] = x[vars[k]];
        return xe;
    }

    E energy_;
    std::vector<Element> elements_;
};

}  // namespace sa
