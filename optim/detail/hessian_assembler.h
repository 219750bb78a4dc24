#pragma once
// Assembles a Problem's gradient and projected Hessian over its free variables.
//
// The sparsity pattern (lower triangle, column-major, diagonal always present) and the gather
// lists are computed once per problem structure. Each iteration then
//   1. evaluates every element in parallel into its own slots (value, weight * gradient,
//      weight * Hessian),
//   2. projects each element Hessian in place, in parallel,
//   3. sums slots into each matrix entry and gradient entry, in parallel over entries, each in a
//      fixed order (term, element, local index),
// so that the result is bit-identical for any number of threads.
//
// Quadratic terms (constant Hessian) are evaluated and projected once, at construction: each keeps
// the entries it adds, scaled by its current weight at every assembly.
//
// A term whose elements declare a Hessian block B (optim/element_energy.h) contributes only its
// element Hessians' diagonal B x B blocks, to the pattern as to the values.
//
// Variables that are fixed, or that no term uses, are not free: they are left out of the system.

#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "optim/hessian_projection.h"
#include "optim/phase_times.h"
#include "optim/problem.h"

namespace sa {

class HessianAssembler {
  public:
    /// Builds the pattern and gather lists for `problem`'s current structure. Quadratic terms
    /// are evaluated at the problem's current variables (any point will do).
    explicit HessianAssembler(const Problem& problem);

    /// True when this assembler was built for `problem` as it is now structured.
    bool matches(const Problem& problem) const;

    Index num_free() const { return static_cast<Index>(variable_of_free_.size()); }
    /// -1 for a variable that is not free, else its row in the system.
    const std::vector<Index>& free_of_variable() const { return free_of_variable_; }
    const std::vector<Index>& variable_of_free() const { return variable_of_free_; }

    struct Evaluation {
        double energy = 0.0;              ///< weighted total; +inf or NaN when not finite
        std::vector<double> term_values;  ///< unweighted value of each term
        Index projected_blocks = 0;       ///< element Hessians the projection changed
    };

    /// Evaluates energy, gradient and projected Hessian at `x`. When the energy is not finite the
    /// gradient and Hessian are not assembled. Adds the phase times to `times`.
    Evaluation evaluate(const Problem& problem, const Eigen::VectorXd& x, ProjectionMode mode,
                        double epsilon, PhaseTimes& times);

    /// Lower triangle of the Hessian over the free variables (valid after evaluate()).
    const Eigen::SparseMatrix<double>& hessian() const { return hessian_; }
    Eigen::SparseMatrix<double>& hessian() { return hessian_; }
    /// Gradient over the free variables (valid after evaluate()).
    const Eigen::VectorXd& gradient() const { return gradient_; }
    /// Position of entry (j, j) in hessian().valuePtr().
    const std::vector<std::int64_t>& diagonal_positions() const { return diagonal_position_; }

  private:
    struct QuadraticPart {
        TermId term;
        std::vector<std::int64_t> position;  ///< into the value array
        std::vector<double> value;           ///< unweighted, projected
    };

    std::uint64_t problem_id_;
    std::uint64_t structure_version_;
    std::vector<Index> free_of_variable_;
    std::vector<Index> variable_of_free_;

    std::vector<std::int64_t> gradient_offset_;  ///< per term, into gradient_slots_
    std::vector<std::int64_t> hessian_offset_;   ///< per term, into hessian_slots_ (-1: quadratic)
    std::vector<double> gradient_slots_;
    std::vector<double> hessian_slots_;

    std::vector<std::int64_t> gradient_source_begin_;  ///< per free variable, size num_free + 1
    std::vector<std::int64_t> gradient_source_;
    std::vector<std::int64_t> entry_source_begin_;  ///< per matrix entry, size nnz + 1
    std::vector<std::int64_t> entry_source_;
    std::vector<QuadraticPart> quadratic_parts_;

    Eigen::SparseMatrix<double> hessian_;
    Eigen::VectorXd gradient_;
    std::vector<std::int64_t> diagonal_position_;
};

}  // namespace sa
