#pragma once
// A term: one element energy applied to many elements, each element naming some entries of the
// problem's variable vector, times a weight the caller may change between iterations.
//
// `Term` is the type-erased interface the assembler and the line search use. Two implementations:
// EnergyTerm<E> (energy_term.h) for an ElementEnergy of fixed arity N, every element naming N
// variables, and DynamicEnergyTerm<E> (dynamic_energy_term.h) for a DynamicElementEnergy, each
// element naming its own number. Problem::add_term() makes either.
//
// Slot layout used by evaluate()/project() (TermLayout gives the offsets): element e of arity n
// and Hessian block B (hessian_block, n for a dense element) owns gradient slots
// [begin(e), begin(e) + n) and Hessian slots [hessian_begin(e), hessian_begin(e) + n B): its
// n / B diagonal B x B blocks, each column-major, block after block (for B = n, the n x n
// Hessian column-major). hessian_slot(B, column, row) gives the place of an entry of a block
// within the element's slots.

#include <cstdint>
#include <string>

#include "optim/hessian_projection.h"
#include "optim/types.h"

namespace sa {

/// The place of entry (row, column) of an element Hessian within its slots (the layout above);
/// row and column in the same B x B block.
inline std::int64_t hessian_slot(int B, int column, int row) {
    return std::int64_t(column / B) * B * B + std::int64_t(column % B) * B + row % B;
}

/// Where a term's elements keep their variable indices and slots: arrays owned by the term,
/// valid while it lives.
struct TermLayout {
    Index num_elements = 0;
    /// Every element's variable indices, element after element.
    const Index* variables = nullptr;
    /// Run-time arity: element e's are variables[offsets[e] .. offsets[e + 1]) (num_elements + 1
    /// entries). Null for a fixed arity: element e's begin at e * arity.
    const std::int64_t* offsets = nullptr;
    /// Run-time arity with dense element Hessians: element e's Hessian slots begin at
    /// hessian_offsets[e] (num_elements + 1 entries). Null otherwise: at begin(e) * block.
    const std::int64_t* hessian_offsets = nullptr;
    /// The arity of every element (fixed), or the largest (run-time).
    int arity = 0;
    /// B of the Hessian blocks, or 0 when each element's Hessian is one block of its arity.
    int block = 0;

    std::int64_t begin(Index e) const { return offsets ? offsets[e] : std::int64_t(e) * arity; }
    int arity_of(Index e) const { return offsets ? int(offsets[e + 1] - offsets[e]) : arity; }
    int block_of(Index e) const { return block > 0 ? block : arity_of(e); }
    std::int64_t hessian_begin(Index e) const {
        return hessian_offsets ? hessian_offsets[e] : begin(e) * block;
    }
    /// The variable indices of all elements: the gradient slots a term needs.
    std::int64_t num_entries() const { return begin(num_elements); }
    /// The Hessian slots a term needs.
    std::int64_t num_hessian_slots() const { return hessian_begin(num_elements); }
};

class Term {
  public:
    Term(std::string name, double weight) : name_(std::move(name)), weight_(weight) {}
    virtual ~Term() = default;
    Term(const Term&) = delete;
    Term& operator=(const Term&) = delete;

    const std::string& name() const { return name_; }
    double weight() const { return weight_; }
    /// Throws InvalidArgumentError unless `weight` is finite and >= 0.
    void set_weight(double weight);

    virtual TermLayout layout() const = 0;
    Index num_elements() const { return layout().num_elements; }
    /// The number of variables element e names, and their indices.
    int element_arity(Index e) const { return layout().arity_of(e); }
    const Index* element_variables(Index e) const {
        const TermLayout l = layout();
        return l.variables + l.begin(e);
    }
    virtual bool is_quadratic() const = 0;
    /// Positive semidefinite Hessian everywhere: never projected (element_energy.h).
    virtual bool is_convex() const = 0;
    virtual bool has_max_step() const = 0;

    /// Unweighted sum of the element values at `x`; +inf as soon as one element is infeasible.
    /// The sum is formed in the same order for any number of threads.
    virtual double value(const Eigen::VectorXd& x) const = 0;
    /// Unweighted sum of the element values; writes `scale` times each element's gradient into
    /// `gradient_slots` and, unless it is null, `scale` times its Hessian into `hessian_slots`.
    virtual double evaluate(const Eigen::VectorXd& x, double scale, double* gradient_slots,
                            double* hessian_slots) const = 0;
    /// Projects every element Hessian in `hessian_slots` in place; returns how many changed. A
    /// convex term's (is_convex()) are positive semidefinite already and left as they are.
    virtual Index project(const Eigen::VectorXd& x, double* hessian_slots, ProjectionMode mode,
                          double epsilon) const = 0;
    /// Smallest max_step over the elements (+inf when the energy has none).
    virtual double max_step(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) const = 0;
    /// The unweighted value of element `e` (for reports and tests).
    virtual double element_value(Index e, const Eigen::VectorXd& x) const = 0;

  protected:
    /// Elements per task: fixed, so that sums are split the same way on any thread count.
    static constexpr Index kGrain = 512;

  private:
    std::string name_;
    double weight_;
};

}  // namespace sa
