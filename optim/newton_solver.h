#pragma once
// Projected Newton with a barrier-aware backtracking line search (the paper's section 4.4).
//
// Each iteration evaluates E, its gradient g and the per-element projected Hessian H at x,
// adds each variable block's Hessian shift, factors H (adding an escalating diagonal tau on the
// blocks that allow it while the factorization fails), solves H d = -g, and searches along d:
// trials start from the previous accepted step (doubled after a first-trial success, capped at
// the initial step), stay below max_step_fraction of the largest feasible step, and halve until
// E decreases enough. An infeasible trial point is never evaluated when the energies provide
// max_step; a +inf trial is rejected in any case.
//
// The solver keeps its Hessian pattern and symbolic factorization between solve() calls while
// the problem's structure is unchanged, so a caller that solves a sequence of problems of the
// same structure (or resumes one) pays the setup once. Both are made after the callbacks of
// iteration 0, so a solve that a callback ends there (the start is good enough) pays nothing.

#include <memory>

#include "optim/linear_solver.h"
#include "optim/newton_options.h"
#include "optim/newton_summary.h"
#include "optim/problem.h"

namespace sa {

class HessianAssembler;  // optim/detail/hessian_assembler.h

class NewtonSolver {
  public:
    explicit NewtonSolver(NewtonOptions options = {});
    ~NewtonSolver();

    const NewtonOptions& options() const { return options_; }
    NewtonOptions& options() { return options_; }

    /// Minimizes the problem's energy from its current variables; the problem holds the last
    /// accepted iterate afterwards (also when an exception from an element energy escapes).
    /// Throws InvalidArgumentError when the options are invalid.
    NewtonSummary solve(Problem& problem);

  private:
    NewtonSummary run(Problem& problem);

    NewtonOptions options_;
    std::unique_ptr<HessianAssembler> assembler_;
    std::unique_ptr<LinearSolver> linear_solver_;
    LinearSolverType requested_solver_ = LinearSolverType::kCholmodSupernodal;
    double last_regularization_ = 0.0;
};

/// Convenience: NewtonSolver(options).solve(problem).
NewtonSummary solve(Problem& problem, const NewtonOptions& options = {});

}  // namespace sa
