#pragma once
// Options of the Newton solver: a plain struct with documented defaults. is_valid() names the
// first field that breaks its rule; NewtonSolver::solve() throws InvalidArgumentError with that
// message.

#include <limits>
#include <string>
#include <vector>

#include "optim/hessian_projection.h"
#include "optim/iteration_callback.h"
#include "optim/linear_solver_type.h"

namespace sa {

struct LineSearchOptions {
    /// First trial step of the first iteration (the paper's alpha_0 = 1).
    double initial_step = 1.0;
    /// Start each line search from the previous accepted step, doubled when that step was taken
    /// at its first trial, never above initial_step (section 4.4). When false, every line search
    /// starts from initial_step.
    bool reuse_previous_step = true;
    /// Trials stay below this fraction of the largest feasible step, so that no trial point is
    /// infeasible. In (0, 1).
    double max_step_fraction = 0.9;
    /// Each rejected trial multiplies the step by this factor. In (0, 1).
    double backtracking_factor = 0.5;
    /// Sufficient decrease: accept when E(x + a d) <= E(x) + armijo * a * g.d. In [0, 1); 0 means
    /// any decrease.
    double armijo = 1e-4;
    /// Trials before the line search reports failure.
    int max_trials = 60;
    /// Longer steps than Newton's when its model overestimates the curvature: when the first
    /// trial is the full step (initial_step) and E fell by more than the quadratic model
    /// predicted, the step is doubled while E keeps falling, within max_step_fraction of the
    /// largest feasible step. Per-element Hessian projection raises the curvature where an
    /// element's Hessian is indefinite, and an exponential barrier curves up faster than its
    /// model: the full step is then too short every time, and Newton converges linearly. For a
    /// fixed energy minimized to convergence; off where the energy changes between steps (a
    /// continuation), whose iterates need not approach a minimizer.
    bool expand = false;
};

/// Diagonal regularization after a failed factorization (section 4.4, step 3): tau is added to
/// the diagonal of the variables whose block allows it, and multiplied by `factor` after every
/// further failure, up to `max`. An iteration that needed tau starts the next one's escalation
/// at tau / factor instead of `initial`.
struct RegularizationOptions {
    double initial = 1e-5;
    double factor = 10.0;
    double max = 1e16;
};

struct NewtonOptions {
    /// Newton steps before stopping with kMaxIterations.
    int max_iterations = 200;
    /// Wall-clock limit in seconds, checked before the Hessian's setup (its pattern and symbolic
    /// analysis), every iteration and every factorization retry.
    double max_time_seconds = std::numeric_limits<double>::infinity();

    /// Converged when the largest |gradient entry| over the free variables is <= this. 0 = off.
    double gradient_tolerance = 1e-10;
    /// Converged when the predicted decrease -g.d / 2 is <= this * max(1, |E|). 0 = off.
    double decrement_tolerance = 1e-14;
    /// Converged when a step changes E by at most this * max(1, |E|) (at fixed weights). 0 = off.
    double function_tolerance = 0.0;

    /// Per-element Hessian projection and its epsilon (smallest eigenvalue kept).
    ProjectionMode projection = ProjectionMode::kClamp;
    double projection_epsilon = 1e-8;

    LineSearchOptions line_search;
    RegularizationOptions regularization;
    LinearSolverType linear_solver = LinearSolverType::kAuto;

    /// Worker threads for evaluation and assembly; 0 = all cores. Results do not depend on it.
    int num_threads = 0;

    /// Called once before the first step and after every step; see IterationCallback.
    std::vector<IterationCallback> callbacks;

    /// True when every field is in range; otherwise false and `error` (if given) names the first
    /// offending field, its value and the rule.
    bool is_valid(std::string* error = nullptr) const;
};

}  // namespace sa
