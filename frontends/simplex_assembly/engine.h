#pragma once
// The Simplex Assembly engine: the paper's section 4 in one place, for every front-end.
//
// Design note
// -----------
// The engine optimizes per-simplex affine maps (A_s, T_s) of d = 2 or 3 and knows no mesh.
//
// Variables (4.4: "we stack all A_i and T_p ... to form the variable vector X"), in one of two
// layouts:
//   linear parts   vec(A_s) (column-major) for every simplex s in [0, n), in whatever frame the
//                  caller uses for s, then T_s for the simplices the caller lists: r-SA the tagged
//                  simplices Omega_s of 4.3, f-SA all of them (5.1), the integrable field of 4.5
//                  none;
//   corner copies  v-SA (5.1): the images of each simplex's D + 1 rest corners; A_s and T_s are
//                  linear in them (A_s = [x_1 - x_0 | ... | x_D - x_0] E_s^-1).
// linear_variables(s), translation_variables(s), affine_variables(s) and image_coefficients(s, u)
// name a simplex's variables, so that no front-end builds flat indices by hand.
//
// Terms, three kinds (E of Eq. 10 is their sum):
//   1. per-simplex energies of A (arity D*D; element s is simplex s, a subset goes through
//      ReindexedEnergy): the mapping energy E_m (a built-in distortion, |A - A0|^2, a user's
//      energy of A) and barriers E_C (DistortionBarrier, bounded or not, several at once with
//      their own bounds). In the corner layout they are evaluated through the copies by
//      VertexSimplexEnergy, the adapter the mesh driver's vertex stage uses too.
//   2. assembly terms, squares of linear functions of (A, T), weighted by lambda: edge (Eq. 7),
//      handle (Eq. 8), vertex (Eq. 9), full-variable (Eqs. 2, 3), the curl of Eq. 11 with its
//      fixed rotations, and any linear constraint |C_e x - b_e|^2 (LinearConstraintEnergy:
//      planarity a^T A_i e = 0, a vertex on a plane, a user's own). Their unweighted sum is
//      E~_assembly.
//   3. barriers over several simplices: the boundary-angle barrier E_theta of 5.1 (2D), the 3D
//      angle barriers of PolyCube.
// Kinds 1 and 3 form "the barrier side" mu E_m + E_C of the schedule.
//
// run() is projected Newton (optim/newton_solver.h) with
//   - the lambda schedule of 4.4: lambda_0 = lambda_min, then after every step
//         lambda = min(lambda_min max((barrier side) / E~_assembly, 1), lambda_max);
//   - the Hessian modification of 4.4: each element's block projected (eigenvalues clamped by
//     default; kShift is the paper's -kappa + 1e-8), translation_shift * lambda added to the
//     translations' diagonal (Hessian only; the paper's 1e-6), tau escalating on the diagonal
//     while the factorization fails (NewtonOptions::regularization);
//   - termination: E~_assembly < assembly_tolerance and E (at the step's lambda) changed by less
//     than energy_tolerance of itself in the step (the paper's test); or lambda at lambda_max and
//     that same change (ours: the weights no longer move, E has converged without assembling); or
//     the front-end's hook (the mesh driver's hand-over by Eq. 6); or max_iterations,
//     max_time_seconds, or a numerical failure of Newton. The result says which (AssemblyStop).
// minimize_without_schedule() is the same Newton, Hessian modification and relative-change test
// for a problem without assembly terms (the mesh driver's vertex stage).
//
// What a front-end supplies: the layout and the start (disassembled, inside the barriers'
// feasible set, 4.2), the terms, the fixed simplices, and a hook called after every iteration.
// Recovery, the vertex stage and verification are the front-end's (simplex_assembly.h).
// This is the only place with lambda-schedule, termination or Hessian-modification logic.

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "energies/linear_constraint_energy.h"
#include "energies/reindexed_energy.h"
#include "energies/vertex_copy_energies.h"
#include "optim/errors.h"
#include "optim/hessian_projection.h"
#include "optim/linear_solver.h"
#include "optim/logger.h"
#include "optim/newton_summary.h"
#include "optim/problem.h"

namespace sa {

/// One iteration of the assembly, as the paper's Figure 4 plots it.
struct AssemblyRecord {
    int iteration = 0;
    double energy = 0.0;    ///< E at the lambda of this step
    double assembly = 0.0;  ///< E~_assembly (unweighted)
    double barrier = 0.0;   ///< the barrier side mu E_m + E_C (+ kind-3 barriers), weighted
    double lambda = 0.0;    ///< lambda used for this step
    double step = -1.0;     ///< accepted step length (-1 at iteration 0)
    int line_search_trials = -1;
    double time = 0.0;  ///< seconds since the optimization started
};

/// Why run() stopped.
enum class AssemblyStop {
    kAssembled,             ///< E~ < assembly_tolerance and E stopped changing (the paper's test)
    kConvergedAtLambdaMax,  ///< lambda at lambda_max and E stopped changing, not assembled
    kHook,                  ///< the front-end's hook stopped it (its reason is the message)
    kNoFreeVariables,       ///< every variable is fixed
    kMaxIterations,
    kMaxTime,
    kLineSearchFailed,
    kFactorizationFailed,
    kInfeasibleStart,  ///< a barrier is +inf at the start: the start is outside the feasible set
    kNonFinite,
};
std::string to_string(AssemblyStop stop);

/// The schedule, Hessian modification and termination, with the paper's constants (4.4).
struct AssemblyEngineOptions {
    double lambda_min = 1e3;
    double lambda_max = 1e16;
    /// E~_assembly below which the simplices count as assembled.
    double assembly_tolerance = 1e-12;
    /// Relative change of E within a step below which E has converged (0 = never).
    double energy_tolerance = 1e-8;
    int max_iterations = 200;
    double max_time_seconds = kInfinity;
    /// Per-element Hessian projection (DESIGN.md: clamping converged in fewer iterations than
    /// the paper's shift, kShift).
    ProjectionMode projection = ProjectionMode::kClamp;
    double projection_epsilon = 1e-8;
    /// Hessian-only shift on the translations, times lambda (the paper's 1e-6; 0 = none).
    double translation_shift = 0.0;
    LinearSolverType linear_solver = LinearSolverType::kAuto;
    int num_threads = 0;  ///< 0 = all cores; results do not depend on it

    /// Throws InvalidArgumentError naming the first bad field and its value.
    void validate() const;
};

/// What the front-end does between iterations.
struct AssemblyHooks {
    /// Receives a header and one progress row per iteration.
    Logger logger;
    /// Called after every iteration (record 0: the start) with the current variables; a
    /// non-empty return value stops the run there (AssemblyStop::kHook, the text as its reason):
    /// the mesh driver's hand-over once the mesh recovered by Eq. 6 is good enough.
    std::function<std::string(const AssemblyRecord&, const Eigen::VectorXd& x)> after_iteration;
};

struct AssemblyRun {
    AssemblyStop stop = AssemblyStop::kMaxIterations;
    std::string message;                  ///< why it stopped, in a sentence
    bool assembled = false;               ///< E~_assembly < assembly_tolerance at the end
    double final_assembly = 0.0;          ///< E~_assembly at the last iterate
    double final_lambda = 0.0;            ///< lambda of the last iteration
    std::vector<AssemblyRecord> records;  ///< record 0 = the start
    NewtonSummary newton;                 ///< iterations, phase times
    double time = 0.0;                    ///< seconds in run()
};

/// A linear constraint over N named variables: coefficients * x[variables] = rhs (R rows).
template <int N, int R>
struct LinearConstraint {
    std::array<Index, N> variables;
    LinearConstraintRows<N, R> rows;
};

/// A linear constraint on one simplex's linear part: coefficients * vec(A_s) = rhs, in either
/// layout (in the corner layout the engine composes it with A_s's map from the copies).
template <int D, int R>
struct LinearPartConstraint {
    Index simplex = 0;
    LinearConstraintRows<D * D, R> rows;
};

template <int D>
class SimplexAssemblyEngine {
  public:
    static constexpr int kLinear = D * D;      ///< variables of vec(A_s)
    static constexpr int kAffine = D * D + D;  ///< of (vec(A_s), T_s), or of the D + 1 copies
    using Corners = Eigen::Matrix<double, D, D + 1>;
    using ImageMap = Eigen::Matrix<double, D, kAffine>;             ///< see image_coefficients()
    using LinearPartMap = Eigen::Matrix<double, kLinear, kAffine>;  ///< see linear_part_map()
    enum class Layout { kLinearParts, kCornerCopies };

    /// The linear-part layout: A_s = linear[s], then T_s for the listed simplices, in that order.
    SimplexAssemblyEngine(const std::vector<Mat<D>>& linear,
                          const std::vector<std::pair<Index, Vec<D>>>& translations = {});
    /// The corner-copy layout (v-SA): corners[s] column k is the image of simplex s's rest corner
    /// rest_corners[s].col(k); rest_edge_inverse[s] = [c_1 - c_0 | ... | c_D - c_0]^-1.
    static SimplexAssemblyEngine corner_copies(const std::vector<Corners>& corners,
                                               std::vector<Corners> rest_corners,
                                               std::vector<Mat<D>> rest_edge_inverse);

    Layout layout() const { return layout_; }
    Index num_simplices() const { return num_simplices_; }
    Problem& problem() { return problem_; }
    const Problem& problem() const { return problem_; }

    // Variables of a simplex. Each throws InvalidArgumentError where the layout has none.
    /// vec(A_s) (linear-part layout).
    std::array<Index, kLinear> linear_variables(Index s) const;
    bool has_translation(Index s) const;
    /// T_s (linear-part layout, a simplex given a translation).
    std::array<Index, D> translation_variables(Index s) const;
    /// (vec(A_s), T_s) in the linear-part layout, the D + 1 copies in the corner layout.
    std::array<Index, kAffine> affine_variables(Index s) const;
    /// The image A_s u + T_s of the rest point u (in s's frame) as a linear function of
    /// affine_variables(s): image = coefficients * x[affine_variables(s)].
    ImageMap image_coefficients(Index s, const Vec<D>& u) const;
    /// vec(A_s) as a linear function of affine_variables(s): vec(A_s) = map * x[affine(s)]
    /// ([I 0] in the linear-part layout; [x_1 - x_0 | ...] E_s^-1 in the corner layout).
    LinearPartMap linear_part_map(Index s) const;

    /// Keeps A_s and T_s (or its copies) at their start.
    void fix_simplex(Index s);

    // Reading the variables back.
    Mat<D> linear_part(const Eigen::VectorXd& x, Index s) const;
    std::vector<Mat<D>> linear_parts(const Eigen::VectorXd& x) const;
    /// The translations the variables determine: the listed simplices (linear-part layout) or
    /// every simplex (corner layout: the image of the frame's origin).
    std::vector<std::pair<Index, Vec<D>>> known_translations(const Eigen::VectorXd& x) const;

    // Terms. Each returns the problem's TermId.
    /// Kind 1 on every simplex: element s of `energy` is simplex s.
    template <ElementEnergy E>
    TermId add_simplex_energy(std::string name, E energy, double weight = 1.0);
    /// Kind 1 on `simplices` only: element s of `energy` is still simplex s (re-indexed).
    template <ElementEnergy E>
    TermId add_simplex_energy(std::string name, std::shared_ptr<const E> energy,
                              std::vector<Index> simplices, double weight = 1.0);
    /// Kind 3: a barrier over several simplices, on variables named by the helpers above.
    template <ElementEnergy E>
    TermId add_barrier(std::string name, E energy,
                       std::vector<std::array<Index, E::arity>> elements, double weight = 1.0);
    /// Kind 2: an assembly term (quadratic), weighted by lambda.
    template <ElementEnergy E>
    TermId add_assembly_term(std::string name, E energy,
                             std::vector<std::array<Index, E::arity>> elements);
    /// Kind 2: linear constraints over named variables.
    template <int N, int R>
    TermId add_linear_constraints(std::string name,
                                  const std::vector<LinearConstraint<N, R>>& constraints);
    /// Kind 2: linear constraints on single linear parts, in either layout.
    template <int R>
    TermId add_linear_part_constraints(std::string name,
                                       const std::vector<LinearPartConstraint<D, R>>& constraints);

    const std::vector<TermId>& assembly_terms() const { return assembly_terms_; }
    /// Kinds 1 and 3.
    const std::vector<TermId>& barrier_terms() const { return barrier_terms_; }
    /// E~_assembly (unweighted) at the current variables.
    double assembly_energy() const;

    /// The schedule of 4.4 from the current variables; they hold the last iterate afterwards.
    AssemblyRun run(const AssemblyEngineOptions& options, const AssemblyHooks& hooks = {});

  private:
    struct CornerTag {};
    SimplexAssemblyEngine(CornerTag, Eigen::VectorXd x, Index n);
    void check_simplex(Index s) const;
    void declare_blocks();

    Layout layout_;
    Index num_simplices_;
    Problem problem_;
    std::vector<Index> translation_offset_;  ///< per simplex: offset of T_s, or -1
    std::vector<Index> translated_;          ///< simplices with T_s, in variable order
    std::vector<Corners> rest_corners_;      ///< corner layout
    std::vector<Mat<D>> rest_inverse_;       ///< corner layout
    std::vector<TermId> assembly_terms_, barrier_terms_;
    BlockId translation_block_ = -1;
    bool blocks_declared_ = false;
};

/// Newton on a problem without assembly terms (the vertex stage) with the engine's Hessian
/// modification and termination: E changes by less than energy_tolerance (relative) in a step,
/// the Newton decrement vanishes, or the limits. Rows "P<k> ..." go to `logger`.
NewtonSummary minimize_without_schedule(Problem& problem, const AssemblyEngineOptions& options,
                                        const Logger& logger = {});

// ---- templates -------------------------------------------------------------------------------

template <int D>
template <ElementEnergy E>
TermId SimplexAssemblyEngine<D>::add_simplex_energy(std::string name, E energy, double weight) {
    static_assert(E::arity == kLinear, "a per-simplex energy is an energy of vec(A)");
    TermId id;
    if (layout_ == Layout::kLinearParts) {
        std::vector<std::array<Index, kLinear>> elements(num_simplices_);
        for (Index s = 0; s < num_simplices_; ++s) elements[s] = linear_variables(s);
        id = problem_.add_term(std::move(name), std::move(energy), std::move(elements), weight);
    } else {
        std::vector<std::array<Index, kAffine>> elements(num_simplices_);
        for (Index s = 0; s < num_simplices_; ++s) elements[s] = affine_variables(s);
        id = problem_.add_term(std::move(name),
                               VertexSimplexEnergy<D, E>(std::move(energy), rest_inverse_),
                               std::move(elements), weight);
    }
    barrier_terms_.push_back(id);
    return id;
}

template <int D>
template <ElementEnergy E>
TermId SimplexAssemblyEngine<D>::add_simplex_energy(std::string name,
                                                    std::shared_ptr<const E> energy,
                                                    std::vector<Index> simplices, double weight) {
    static_assert(E::arity == kLinear, "a per-simplex energy is an energy of vec(A)");
    for (Index s : simplices) check_simplex(s);
    TermId id;
    if (layout_ == Layout::kLinearParts) {
        std::vector<std::array<Index, kLinear>> elements;
        for (Index s : simplices) elements.push_back(linear_variables(s));
        id = problem_.add_term(std::move(name),
                               ReindexedEnergy<E>(std::move(energy), std::move(simplices)),
                               std::move(elements), weight);
    } else {
        std::vector<std::array<Index, kAffine>> elements;
        std::vector<Mat<D>> rest_inverse;
        for (Index s : simplices) {
            elements.push_back(affine_variables(s));
            rest_inverse.push_back(rest_inverse_[s]);
        }
        id = problem_.add_term(std::move(name),
                               VertexSimplexEnergy<D, ReindexedEnergy<E>>(
                                   ReindexedEnergy<E>(std::move(energy), std::move(simplices)),
                                   std::move(rest_inverse)),
                               std::move(elements), weight);
    }
    barrier_terms_.push_back(id);
    return id;
}

template <int D>
template <ElementEnergy E>
TermId SimplexAssemblyEngine<D>::add_barrier(std::string name, E energy,
                                             std::vector<std::array<Index, E::arity>> elements,
                                             double weight) {
    const TermId id =
        problem_.add_term(std::move(name), std::move(energy), std::move(elements), weight);
    barrier_terms_.push_back(id);
    return id;
}

template <int D>
template <ElementEnergy E>
TermId SimplexAssemblyEngine<D>::add_assembly_term(
    std::string name, E energy, std::vector<std::array<Index, E::arity>> elements) {
    static_assert(is_quadratic_energy<E>(),
                  "an assembly term is a sum of squares of linear functions: is_quadratic");
    const TermId id = problem_.add_term(std::move(name), std::move(energy), std::move(elements));
    assembly_terms_.push_back(id);
    return id;
}

template <int D>
template <int N, int R>
TermId SimplexAssemblyEngine<D>::add_linear_constraints(
    std::string name, const std::vector<LinearConstraint<N, R>>& constraints) {
    std::vector<LinearConstraintRows<N, R>> rows;
    std::vector<std::array<Index, N>> elements;
    rows.reserve(constraints.size());
    elements.reserve(constraints.size());
    for (const LinearConstraint<N, R>& c : constraints) {
        for (Index v : c.variables) {
            if (v < 0 || v >= problem_.num_variables()) {
                throw InvalidArgumentError(name + ": constraint " +
                                           std::to_string(elements.size()) + " names variable " +
                                           std::to_string(v) + ", outside [0, " +
                                           std::to_string(problem_.num_variables()) + ")");
            }
        }
        rows.push_back(c.rows);
        elements.push_back(c.variables);
    }
    return add_assembly_term(std::move(name), LinearConstraintEnergy<N, R>(std::move(rows)),
                             std::move(elements));
}

template <int D>
template <int R>
TermId SimplexAssemblyEngine<D>::add_linear_part_constraints(
    std::string name, const std::vector<LinearPartConstraint<D, R>>& constraints) {
    if (layout_ == Layout::kLinearParts) {
        std::vector<LinearConstraint<kLinear, R>> rows;
        rows.reserve(constraints.size());
        for (const LinearPartConstraint<D, R>& c : constraints)
            rows.push_back({linear_variables(c.simplex), c.rows});
        return add_linear_constraints<kLinear, R>(std::move(name), rows);
    }
    std::vector<LinearConstraint<kAffine, R>> rows;
    rows.reserve(constraints.size());
    for (const LinearPartConstraint<D, R>& c : constraints) {
        rows.push_back({affine_variables(c.simplex),
                        {c.rows.coefficients * linear_part_map(c.simplex), c.rows.rhs}});
    }
    return add_linear_constraints<kAffine, R>(std::move(name), rows);
}

extern template class SimplexAssemblyEngine<2>;
extern template class SimplexAssemblyEngine<3>;

}  // namespace sa
