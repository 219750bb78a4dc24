#pragma once
// The Simplex Assembly engine: the paper's section 4 in one place, for every front-end.
//
// Design note
// -----------
// The engine optimizes per-simplex affine maps (A_s, T_s) of d = 2 or 3 and knows no mesh.
//
// Variables (4.4: "we stack all A_i and T_p ... to form the variable vector X"), in one of three
// layouts:
//   linear parts      vec(A_s) (column-major) for every simplex s in [0, n), in whatever frame
//                     the caller uses for s, then T_s for the simplices the caller lists: r-SA the
//                     tagged simplices Omega_s of 4.3, f-SA all of them (5.1), the integrable
//                     field of 4.5 none;
//   corner copies     v-SA (5.1): the images of each simplex's D + 1 rest corners; A_s and T_s
//                     are linear in them (A_s = [x_1 - x_0 | ... | x_D - x_0] E_s^-1);
//   vertex positions  the same with the copies of a mesh vertex identified: one position per
//                     vertex (the mesh driver's vertex stage, after assembly; Newton on vertex
//                     positions from a valid start).
// linear_variables(s), translation_variables(s), affine_variables(s), vertex_variables(v) and
// image_coefficients(s, u) name the variables, so that no front-end builds flat indices by hand.
//
// Terms, three kinds (E of Eq. 10 is their sum):
//   1. per-simplex energies of A (arity D*D; element k on simplex k, or on a listed simplex):
//      the mapping energy E_m (a built-in distortion, |A - A0|^2, a user's energy of A) and
//      barriers E_C (DistortionBarrier on any distortion, bounded or not, several at once with
//      their own bounds). In the corner and vertex layouts they are evaluated through the
//      positions by VertexSimplexEnergy (A = X E^-1, Hessian projected in A).
//   2. assembly terms, squares of linear functions of the variables, weighted by lambda: edge
//      (Eq. 7), handle (Eq. 8), vertex (Eq. 9), full-variable (Eqs. 2, 3), the curl of Eq. 11
//      with its fixed rotations, and any linear constraint |C_e x - b_e|^2
//      (LinearConstraintEnergy: PolyCube planarity a^T A_i e = 0, a vertex on a plane, a user's
//      own; add_linear_constraints, add_linear_part_constraints). Their unweighted sum is
//      E~_assembly.
//   3. barriers over several simplices (add_barrier): the boundary-angle barrier E_theta of 5.1
//      (2D), the 3D angle barriers of PolyCube.
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
//   Without assembly terms there is no schedule: plain projected Newton to the same relative
//   change of E or a vanishing Newton decrement (AssemblyStop::kConverged).
//
// What a front-end supplies: the layout and the start (disassembled, inside the barriers'
// feasible set, 4.2), the terms, the fixed simplices or vertices, and a hook called after every
// iteration. Recovery, the vertex stage and verification are the mesh driver's
// (frontends/simplex_assembly/map_solve.h; a front-end's own kind-2 and kind-3 terms reach its
// engines through assembly_plugin.h). This is the only place with lambda-schedule, termination or
// Hessian-modification logic.

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "energies/distortion_barrier.h"
#include "energies/linear_constraint_energy.h"
#include "energies/reindexed_energy.h"
#include "energies/simplex_energy.h"
#include "energies/vertex_copy_energies.h"
#include "frontends/simplex_assembly/engine_options.h"
#include "optim/errors.h"
#include "optim/logger.h"
#include "optim/newton_summary.h"
#include "optim/problem.h"

namespace sa {

/// What the front-end does between iterations.
struct AssemblyHooks {
    /// Receives a header and one progress row per iteration.
    Logger logger;
    /// Called after every iteration (record 0: the start) with the current variables; true stops
    /// the run there (AssemblyStop::kHook): the mesh driver's hand-over once the mesh recovered
    /// by Eq. 6 is good enough.
    std::function<bool(const AssemblyRecord&, const Eigen::VectorXd& x)> after_iteration;
};

struct AssemblyRun {
    AssemblyStop stop = AssemblyStop::kMaxIterations;
    bool assembled = false;               ///< E~_assembly < assembly_tolerance at the end
    double final_assembly = 0.0;          ///< E~_assembly at the last iterate
    double final_lambda = 0.0;            ///< lambda of the last iteration
    std::vector<AssemblyRecord> records;  ///< record 0 = the start
    NewtonSummary newton;                 ///< iterations, phase times
    double time = 0.0;                    ///< seconds in run()
};

/// A linear constraint over N named variables: rows.coefficients * x[variables] = rows.rhs.
template <int N, int R>
struct LinearConstraint {
    std::array<Index, N> variables;
    LinearConstraintRows<N, R> rows;
};

/// A linear constraint on one simplex's linear part: coefficients * vec(A_s) = rhs, in any
/// layout (in the corner and vertex layouts the engine composes it with A_s's map from the
/// positions).
template <int D, int R>
struct LinearPartConstraint {
    Index simplex = 0;
    LinearConstraintRows<D * D, R> rows;
};

template <int D>
class SimplexAssemblyEngine {
  public:
    static constexpr int kLinear = D * D;      ///< variables of vec(A_s)
    static constexpr int kAffine = D * D + D;  ///< of (vec(A_s), T_s), or of the D + 1 positions
    using Corners = Eigen::Matrix<double, D, D + 1>;
    using ImageMap = Eigen::Matrix<double, D, kAffine>;             ///< see image_coefficients()
    using LinearPartMap = Eigen::Matrix<double, kLinear, kAffine>;  ///< see linear_part_map()
    enum class Layout { kLinearParts, kCornerCopies, kVertexPositions };

    /// The linear-part layout: A_s = linear[s], then T_s for the listed simplices, in that order.
    SimplexAssemblyEngine(const std::vector<Mat<D>>& linear,
                          const std::vector<std::pair<Index, Vec<D>>>& translations = {});
    /// The corner-copy layout (v-SA): corners[s] column k is the image of simplex s's rest corner
    /// rest_corners[s].col(k); rest_edge_inverse[s] = [c_1 - c_0 | ... | c_D - c_0]^-1.
    static SimplexAssemblyEngine corner_copies(const std::vector<Corners>& corners,
                                               std::vector<Corners> rest_corners,
                                               std::vector<Mat<D>> rest_edge_inverse);
    /// The vertex layout: `positions` #V x D (row v the image of vertex v), simplex s has the
    /// vertices simplices[s] (corner k of rest_corners[s] is vertex simplices[s][k]).
    ///
    /// `shared` (empty, or D #V entries) makes single coordinates one variable: coordinate c of
    /// vertex v (index D v + c) is the variable of coordinate shared[D v + c], which must share
    /// with itself. A PolyCube plane is one such variable: every vertex on it keeps one common
    /// coordinate along its normal, which moves. A shared variable starts at the mean of its
    /// coordinates in `positions`; a coordinate that shares another's has no variable of its own
    /// (its slot in the variable vector is left unused), and vertex_variables() names the shared
    /// one.
    static SimplexAssemblyEngine vertex_positions(const Eigen::MatrixXd& positions,
                                                  std::vector<std::array<Index, D + 1>> simplices,
                                                  std::vector<Corners> rest_corners,
                                                  std::vector<Mat<D>> rest_edge_inverse,
                                                  std::vector<Index> shared = {});

    Layout layout() const { return layout_; }
    Index num_simplices() const { return num_simplices_; }
    Problem& problem() { return problem_; }
    const Problem& problem() const { return problem_; }

    // Variables. Each throws InvalidArgumentError where the layout has none.
    /// vec(A_s) (linear-part layout).
    std::array<Index, kLinear> linear_variables(Index s) const;
    bool has_translation(Index s) const;
    /// T_s (linear-part layout, a simplex given a translation).
    std::array<Index, D> translation_variables(Index s) const;
    /// (vec(A_s), T_s) in the linear-part layout, the D + 1 positions of its corners in the
    /// others.
    std::array<Index, kAffine> affine_variables(Index s) const;
    /// The position of vertex v (vertex layout).
    std::array<Index, D> vertex_variables(Index v) const;
    /// Vertex layout: the variable of coordinate c of vertex v, given as i = D v + c (itself
    /// unless shared, see vertex_positions()).
    Index coordinate_variable(Index i) const { return shared_.empty() ? i : shared_[i]; }
    /// The image A_s u + T_s of the rest point u (in s's frame) as a linear function of
    /// affine_variables(s): image = coefficients * x[affine_variables(s)].
    ImageMap image_coefficients(Index s, const Vec<D>& u) const;
    /// vec(A_s) as a linear function of affine_variables(s): vec(A_s) = map * x[affine(s)]
    /// ([I 0] in the linear-part layout; [x_1 - x_0 | ...] E_s^-1 in the others).
    LinearPartMap linear_part_map(Index s) const;

    /// Keeps A_s and T_s (or its positions) at their start.
    void fix_simplex(Index s);
    /// Keeps vertex v at its start (vertex layout).
    void fix_vertex(Index v);

    // Reading the variables back.
    Mat<D> linear_part(const Eigen::VectorXd& x, Index s) const;
    std::vector<Mat<D>> linear_parts(const Eigen::VectorXd& x) const;
    /// The translations the variables determine: the listed simplices (linear-part layout) or
    /// every simplex (the others: the image of the frame's origin).
    std::vector<std::pair<Index, Vec<D>>> known_translations(const Eigen::VectorXd& x) const;
    /// Vertex layout: the positions, #V x D.
    Eigen::MatrixXd positions(const Eigen::VectorXd& x) const;

    // Terms. Each returns the problem's TermId.
    /// Kind 1: element k of `energy` on simplex simplices[k], or element s on simplex s for every
    /// simplex when `simplices` is empty.
    template <ElementEnergy E>
    TermId add_simplex_energy(std::string name, E energy, std::vector<Index> simplices = {},
                              double weight = 1.0);
    /// Kind 3: a barrier over several simplices, on variables named by the helpers above.
    template <ElementEnergy E>
    TermId add_barrier(std::string name, E energy,
                       std::vector<std::array<Index, E::arity>> elements, double weight = 1.0);
    /// The same for an energy of run-time arity (fans, rings, stars of any size).
    template <DynamicElementEnergy E>
    TermId add_barrier(std::string name, E energy, RaggedElements elements, double weight = 1.0);
    /// Kind 2: an assembly term (quadratic), weighted by lambda.
    template <ElementEnergy E>
    TermId add_assembly_term(std::string name, E energy,
                             std::vector<std::array<Index, E::arity>> elements);
    /// Kind 2: linear constraints over named variables. Throws InvalidArgumentError naming the
    /// term and constraint for a variable out of range or a non-finite coefficient.
    template <int N, int R>
    TermId add_linear_constraints(std::string name,
                                  const std::vector<LinearConstraint<N, R>>& constraints);
    /// Kind 2: linear constraints on single linear parts, in any layout.
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
    struct LayoutTag {};
    SimplexAssemblyEngine(LayoutTag, Layout layout, Eigen::VectorXd x, Index n);
    void check_simplex(Index s) const;
    void declare_blocks();
    /// Corner and vertex layouts: variable of coordinate c of corner k of simplex s.
    Index corner_variable(Index s, int k, int c) const;
    /// Corner and vertex layouts: the position of corner k of simplex s.
    Vec<D> corner(const Eigen::VectorXd& x, Index s, int k) const;

    Layout layout_;
    Index num_simplices_;
    Problem problem_;
    std::vector<Index> translation_offset_;            ///< per simplex: offset of T_s, or -1
    std::vector<Index> translated_;                    ///< simplices with T_s, in order
    std::vector<Corners> rest_corners_;                ///< corner and vertex layouts
    std::vector<Mat<D>> rest_inverse_;                 ///< corner and vertex layouts
    std::vector<std::array<Index, D + 1>> simplices_;  ///< vertex layout
    std::vector<Index> shared_;                        ///< vertex layout: see vertex_positions()
    std::vector<TermId> assembly_terms_, barrier_terms_;
    BlockId translation_block_ = -1;
    bool blocks_declared_ = false;
};

// ---- templates -------------------------------------------------------------------------------

template <int D>
template <ElementEnergy E>
TermId SimplexAssemblyEngine<D>::add_simplex_energy(std::string name, E energy,
                                                    std::vector<Index> simplices, double weight) {
    static_assert(E::arity == kLinear, "a per-simplex energy is an energy of vec(A)");
    if (simplices.empty()) {
        simplices.resize(num_simplices_);
        for (Index s = 0; s < num_simplices_; ++s) simplices[s] = s;
    }
    for (Index s : simplices) check_simplex(s);
    TermId id;
    if (layout_ == Layout::kLinearParts) {
        std::vector<std::array<Index, kLinear>> elements;
        elements.reserve(simplices.size());
        for (Index s : simplices) elements.push_back(linear_variables(s));
        id = problem_.add_term(std::move(name), std::move(energy), std::move(elements), weight);
    } else {
        std::vector<std::array<Index, kAffine>> elements;
        std::vector<Mat<D>> rest_inverse;
        elements.reserve(simplices.size());
        rest_inverse.reserve(simplices.size());
        for (Index s : simplices) {
            elements.push_back(affine_variables(s));
            rest_inverse.push_back(rest_inverse_[s]);
        }
        id = problem_.add_term(
            std::move(name), VertexSimplexEnergy<D, E>(std::move(energy), std::move(rest_inverse)),
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
template <DynamicElementEnergy E>
TermId SimplexAssemblyEngine<D>::add_barrier(std::string name, E energy, RaggedElements elements,
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
        if (!c.rows.coefficients.allFinite() || !c.rows.rhs.allFinite()) {
            throw InvalidArgumentError(name + ": constraint " + std::to_string(elements.size()) +
                                       " has a non-finite coefficient");
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

/// The engine's terms of the per-simplex energy E = __VA_ARGS__ in dimension D, in every layout
/// and restricted (ReindexedEnergy): declared with PREFIX `extern`, compiled with no PREFIX.
#define SA_SIMPLEX_ENERGY_TERMS(PREFIX, D, ...)                                             \
    PREFIX template class EnergyTerm<__VA_ARGS__>;                                          \
    PREFIX template class EnergyTerm<ReindexedEnergy<__VA_ARGS__>>;                         \
    PREFIX template class EnergyTerm<VertexSimplexEnergy<D, __VA_ARGS__>>;                  \
    PREFIX template class EnergyTerm<VertexSimplexEnergy<D, ReindexedEnergy<__VA_ARGS__>>>; \
    PREFIX template TermId SimplexAssemblyEngine<D>::add_simplex_energy(                    \
        std::string, __VA_ARGS__, std::vector<Index>, double);                              \
    PREFIX template TermId SimplexAssemblyEngine<D>::add_simplex_energy(                    \
        std::string, ReindexedEnergy<__VA_ARGS__>, std::vector<Index>, double);

// The built-in energies' terms, E_m + E_C of the options (SimplexEnergy) and a barrier on a
// built-in distortion, are compiled once, in builtin_simplex_terms_2d.cpp and _3d.cpp, rather
// than in every unit that adds one (docs/measurements.md, "Build time").
SA_SIMPLEX_ENERGY_TERMS(extern, 2, SimplexEnergy<2>)
SA_SIMPLEX_ENERGY_TERMS(extern, 3, SimplexEnergy<3>)
SA_SIMPLEX_ENERGY_TERMS(extern, 2, DistortionBarrier<2, BuiltinDistortion<2>>)
SA_SIMPLEX_ENERGY_TERMS(extern, 3, DistortionBarrier<3, BuiltinDistortion<3>>)

}  // namespace sa
