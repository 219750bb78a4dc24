#pragma once
// A problem: a vector of variables and a list of terms, each an element energy summed over many
// elements. Its energy is E(x) = sum_t weight_t * sum_e energy_t(element e's variables).
//
// clang-format off
//   sa::Problem problem(x0);
//   problem.add_term("distortion", MyEnergy{rest}, elements);   // elements: {{i, j, ...}, ...}
//   problem.add_elements<4>("springs", springs,                 // a lambda over the scalar type
//                           [&](auto const& x, sa::Index e) { ... });
//   problem.set_fixed(7);                                       // a pinned variable
//   sa::NewtonSummary summary = sa::NewtonSolver(options).solve(problem);
// clang-format on
//
// Variables may be fixed (they keep their value and leave the linear system), grouped into named
// blocks that carry a Hessian-only diagonal shift and take part, or not, in the regularization the
// Newton loop adds when a factorization fails. point_variables.h gives the variables of mesh
// vertices and simplices; problem_evaluation.h evaluates E, its gradient and projected Hessian
// for callers who run their own loop.

#include <Eigen/Core>
#include <array>
#include <concepts>
#include <cstdint>
#include <iterator>
#include <memory>
#include <ranges>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "optim/dynamic_energy_term.h"
#include "optim/energy_term.h"
#include "optim/errors.h"
#include "optim/lambda_energy.h"

namespace sa {

using TermId = int;
using BlockId = int;

/// A named range of variables [begin, end).
struct VariableBlock {
    std::string name;
    Index begin = 0;
    Index end = 0;
    /// Added to the Hessian diagonal of these variables at every iteration. It changes the
    /// Newton step, never the energy (the paper's 1e-6 * lambda on translations, section 4.4).
    double hessian_shift = 0.0;
    /// Whether these variables receive the diagonal tau that the Newton loop adds, escalating,
    /// when a factorization fails (section 4.4, step 3: only the A_i).
    bool regularize_on_failure = true;
};

/// The sizes of arrays of per-element data (rest shapes, areas, targets, ...) that an element
/// function reads by element index: add_elements() checks each against the number of elements.
struct PerElement {
    std::vector<std::size_t> sizes;
};

/// PerElement{...} of the given arrays: std::vector, std::array, or Eigen matrices with one row
/// per element.
template <class... Arrays>
PerElement per_element(const Arrays&... arrays) {
    auto count = [](const auto& a) -> std::size_t {
        if constexpr (requires { a.rows(); }) {
            return static_cast<std::size_t>(a.rows());
        } else {
            return std::size(a);
        }
    };
    return PerElement{{count(arrays)...}};
}

class Problem {
  public:
    /// A problem over `variables.size()` variables, starting from `variables`.
    explicit Problem(Eigen::VectorXd variables);
    Problem(const Problem&) = delete;
    Problem& operator=(const Problem&) = delete;
    Problem(Problem&&) = default;
    Problem& operator=(Problem&&) = default;

    Index num_variables() const { return static_cast<Index>(variables_.size()); }
    const Eigen::VectorXd& variables() const { return variables_; }
    /// Replaces the current variables (same size; throws otherwise).
    void set_variables(const Eigen::VectorXd& variables);

    /// Adds `energy` over `elements` (each names E::arity variable indices) with `weight`.
    /// Throws InvalidArgumentError naming the term and element for an index out of range, and,
    /// when the energy says how many elements its per-element data covers (an optional member
    /// `num_elements()`, element_energy.h), for a count that differs from elements.size().
    template <ElementEnergy E>
    TermId add_term(std::string name, E energy, std::vector<std::array<Index, E::arity>> elements,
                    double weight = 1.0) {
        if constexpr (HasElementCount<E>) {
            check_element_data(name, elements.size(), {std::size_t(energy.num_elements())},
                               "the energy's per-element data covers");
        }
        for (std::size_t e = 0; e < elements.size(); ++e) {
            for (Index v : elements[e]) check_element_index(name, e, v);
        }
        auto term = std::make_unique<EnergyTerm<E>>(std::move(name), std::move(energy),
                                                    std::move(elements), 1.0);
        term->set_weight(weight);
        terms_.push_back(std::move(term));
        ++structure_version_;
        return static_cast<TermId>(terms_.size() - 1);
    }

    /// Adds `energy` of run-time arity (dynamic_element_energy.h) over `elements`, each naming
    /// its own number of variables, with `weight`. Throws InvalidArgumentError naming the term
    /// and element for an index out of range, an element whose arity differs from the one the
    /// energy's data expects (its optional element_arity(e)) or is not a multiple of its
    /// hessian_block, and for an element count that differs from the energy's num_elements().
    template <DynamicElementEnergy E>
    TermId add_term(std::string name, E energy, RaggedElements elements, double weight = 1.0) {
        if constexpr (HasElementCount<E>) {
            check_element_data(name, std::size_t(elements.size()),
                               {std::size_t(energy.num_elements())},
                               "the energy's per-element data covers");
        }
        constexpr int block = dynamic_hessian_block_of<E>();
        for (Index e = 0; e < elements.size(); ++e) {
            int expected = elements.arity(e);
            if constexpr (HasElementArity<E>) expected = energy.element_arity(e);
            check_element_arity(name, e, elements.arity(e), expected, block);
            for (Index v : elements[e]) check_element_index(name, std::size_t(e), v);
        }
        auto term = std::make_unique<DynamicEnergyTerm<E>>(std::move(name), std::move(energy),
                                                           std::move(elements), 1.0);
        term->set_weight(weight);
        terms_.push_back(std::move(term));
        ++structure_version_;
        return static_cast<TermId>(terms_.size() - 1);
    }

    /// Adds the energy `function(x, e)` of each element e, written once over the scalar type
    /// (lambda_energy.h): x is the element's N variables (Eigen::Matrix<T, N, 1>, T double or
    /// Dual<N>), the value a T. Gradients and Hessians come from automatic differentiation.
    template <int N, class Function>
    TermId add_elements(std::string name, std::vector<std::array<Index, N>> elements,
                        Function&& function, double weight = 1.0) {
        return add_term(std::move(name), lambda_energy<N>(std::forward<Function>(function)),
                        std::move(elements), weight);
    }
    /// The same, first checking that each array of per-element data the function reads has one
    /// entry per element (throws InvalidArgumentError naming the term and both counts).
    template <int N, class Function>
    TermId add_elements(std::string name, std::vector<std::array<Index, N>> elements,
                        const PerElement& data, Function&& function, double weight = 1.0) {
        check_element_data(name, elements.size(), data.sizes, "per-element data");
        return add_elements<N>(std::move(name), std::move(elements),
                               std::forward<Function>(function), weight);
    }

    int num_terms() const { return static_cast<int>(terms_.size()); }
    const Term& term(TermId id) const { return *terms_.at(id); }
    Term& term(TermId id) { return *terms_.at(id); }
    /// Changes a term's weight (the paper's lambda); allowed between iterations.
    void set_weight(TermId id, double weight) { terms_.at(id)->set_weight(weight); }
    double weight(TermId id) const { return terms_.at(id)->weight(); }

    /// Fixes or frees a variable. A fixed variable keeps its current value.
    void set_fixed(Index variable, bool fixed = true);
    /// Fixes or frees several variables (e.g. point_variables<D>(v), a vertex's coordinates).
    template <std::ranges::range Variables>
    requires std::convertible_to<std::ranges::range_value_t<Variables>, Index>
    void set_fixed(const Variables& variables, bool fixed = true) {
        for (Index v : variables) set_fixed(v, fixed);
    }
    bool is_fixed(Index variable) const { return fixed_.at(variable) != 0; }
    Index num_free_variables() const;

    /// Declares a block; blocks may not overlap. Throws on a bad or overlapping range.
    BlockId add_variable_block(std::string name, Index begin, Index end);
    int num_variable_blocks() const { return static_cast<int>(blocks_.size()); }
    const VariableBlock& variable_block(BlockId id) const { return blocks_.at(id); }
    void set_hessian_shift(BlockId id, double shift);
    void set_regularize_on_failure(BlockId id, bool regularize);

    /// The weighted energy at `x`; +inf when an element is infeasible. When `term_values` is
    /// given, it receives each term's unweighted value.
    double value(const Eigen::VectorXd& x, std::vector<double>* term_values = nullptr) const;
    double value() const { return value(variables_); }
    /// The largest step t such that x + s dx stays feasible for all s in [0, t) (min over terms).
    double max_step(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) const;

    /// Changes whenever terms are added or variables fixed/freed: a Hessian pattern and a
    /// symbolic factorization remain valid while (id(), structure_version()) is unchanged.
    std::uint64_t structure_version() const { return structure_version_; }
    /// A number unique to this problem object within the process.
    std::uint64_t id() const { return id_; }

  private:
    void check_element_index(const std::string& term, std::size_t element, Index v) const;
    /// An element of run-time arity: at least one variable, `expected` of them, a multiple of
    /// `block` (when > 0).
    static void check_element_arity(const std::string& term, Index element, int arity, int expected,
                                    int block);
    static void check_element_data(const std::string& term, std::size_t elements,
                                   const std::vector<std::size_t>& sizes, const char* what);

    Eigen::VectorXd variables_;
    std::vector<std::unique_ptr<Term>> terms_;
    std::vector<unsigned char> fixed_;
    std::vector<VariableBlock> blocks_;
    std::uint64_t structure_version_ = 0;
    std::uint64_t id_;
};

}  // namespace sa
