#pragma once
// The Simplex Assembly engine's options and records (engine.h): the schedule, Hessian
// modification and termination of the paper's section 4.4 with its constants, one record per
// iteration, and why a run stopped. Apart from engine.h so that options structs can hold them
// without pulling in the optimizer.

#include <string>

#include "optim/hessian_projection.h"
#include "optim/linear_solver.h"
#include "optim/types.h"

namespace sa {

/// One iteration of the assembly, as the paper's Figure 4 plots it.
struct AssemblyRecord {
    int iteration = 0;
    double energy = 0.0;         ///< E at the lambda of this step
    double energy_change = 0.0;  ///< E before the step minus E after, both at this step's weights
    double assembly = 0.0;       ///< E~_assembly (unweighted)
    double barrier = 0.0;        ///< the barrier side mu E_m + E_C (+ kind-3 barriers), weighted
    double lambda = 0.0;         ///< lambda used for this step
    double step = -1.0;          ///< accepted step length (-1 at iteration 0)
    int line_search_trials = -1;
    double time = 0.0;  ///< seconds since the optimization started
};

/// Why run() stopped.
enum class AssemblyStop {
    kAssembled,             ///< E~ < assembly_tolerance and E stopped changing (the paper's test)
    kConvergedAtLambdaMax,  ///< lambda at lambda_max and E stopped changing, not assembled
    kConverged,             ///< no assembly terms: E stopped changing (Newton's own tests)
    kHook,                  ///< the front-end's hook stopped it (AssemblyHooks::after_iteration)
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
/// Termination: E~_assembly below assembly_tolerance and the relative change of E within a step
/// below energy_tolerance (the paper's), or lambda at lambda_max and that same change below
/// energy_tolerance (ours: the weights no longer move, so E has converged without assembling),
/// or the limits.
struct AssemblyEngineOptions {
    /// The schedule lambda = min(lambda_min max((mu E_m + E_C) / E~, 1), lambda_max).
    double lambda_min = 1e3;
    double lambda_max = 1e16;
    /// E~_assembly below which the simplices count as assembled.
    double assembly_tolerance = 1e-12;
    /// Relative change of E within a step below which E has converged (0 = never).
    double energy_tolerance = 1e-8;
    /// Without assembly terms: end when E stops changing or the Newton decrement vanishes. Off:
    /// only the hook or the limits end the run (a continuation whose hook changes the energy
    /// between steps, where those tests compare values of different energies).
    bool stop_when_converged = true;
    int max_iterations = 200;  ///< of each stage
    /// Wall-clock limit in seconds. The mesh driver gives every stage and submesh what is left
    /// of it; when it runs out, the map reached so far is recovered, verified and reported.
    double max_time_seconds = kInfinity;
    /// Per-element Hessian projection (clamping converged in fewer iterations than the paper's
    /// shift, kShift: docs/measurements.md, "Departures from the paper, measured").
    ProjectionMode projection = ProjectionMode::kClamp;
    double projection_epsilon = 1e-8;
    /// Hessian-only diagonal shift on the translations, times lambda (step 2 of 4.4; the paper
    /// uses 1e-6). Off by default: with many handles (a fixed boundary) r-SA's Omega_s holds
    /// many simplices, and at lambda = 1e16 a shift of 1e10 on their translations freezes them.
    /// Measured on a 750-tet cube with its boundary as handles: with 1e-6 no convergence in 200
    /// iterations (conformal max 1.24), with 0 converged in 24 (conformal max 1.0006, the
    /// optimum being the identity). Redundant translations are still handled: the
    /// regularization tau of step 3 reaches them when a factorization fails.
    double translation_shift = 0.0;
    LinearSolverType linear_solver = LinearSolverType::kAuto;
    int num_threads = 0;  ///< 0 = all cores; results do not depend on it

    /// Throws InvalidArgumentError naming the first bad field and its value.
    void validate() const;
};

}  // namespace sa
