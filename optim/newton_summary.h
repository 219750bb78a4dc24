#pragma once
// The outcome of a Newton solve: why it stopped, the energies, one record per iteration and the
// time spent in each phase. Numerical failures are reported here, never thrown.

#include <string>
#include <vector>

#include "optim/iteration_record.h"
#include "optim/linear_solver_type.h"
#include "optim/phase_times.h"

namespace sa {

enum class TerminationType {
    kConverged,            ///< a tolerance of NewtonOptions was met
    kUserSuccess,          ///< a callback returned kStopSuccess
    kMaxIterations,        ///< NewtonOptions::max_iterations steps without convergence
    kMaxTime,              ///< NewtonOptions::max_time_seconds passed
    kUserAbort,            ///< a callback returned kAbort
    kLineSearchFailed,     ///< no trial step decreased the energy enough
    kFactorizationFailed,  ///< no regularization up to its cap gave a positive-definite matrix
    kInfeasibleStart,      ///< the energy is +inf at the initial variables
    kNonFinite,            ///< the energy, gradient or Hessian became NaN
};

std::string to_string(TerminationType type);

struct NewtonSummary {
    TerminationType termination = TerminationType::kMaxIterations;
    std::string message;  ///< what happened, in a sentence

    double initial_energy = -1.0;
    double final_energy = -1.0;
    double final_gradient_norm = -1.0;  ///< at the last point where it was evaluated

    Index num_variables = 0;
    /// Not fixed and used by a term. This and hessian_nonzeros stay 0 when the solve ends at
    /// iteration 0 before the Hessian's pattern is made (a callback, or the time limit).
    Index num_free_variables = 0;
    std::int64_t hessian_nonzeros = 0;  ///< in the lower triangle
    LinearSolverType linear_solver = LinearSolverType::kCholmodSupernodal;  ///< the one used
    int num_threads = 0;

    std::vector<IterationRecord> iterations;  ///< record 0 = the start
    PhaseTimes times;

    /// Converged or stopped by a callback's success.
    bool success() const {
        return termination == TerminationType::kConverged ||
               termination == TerminationType::kUserSuccess;
    }
    int num_steps() const { return iterations.empty() ? 0 : int(iterations.size()) - 1; }

    /// One line: outcome, energies, steps, time.
    std::string brief_report() const;
    /// The phase times in one line: "setup 0.01, evaluate 0.28, ..., callbacks 0.02" (seconds).
    std::string phase_times() const;
    /// Several lines: problem size, solver, outcome, energies, phase times.
    std::string full_report() const;
};

}  // namespace sa
