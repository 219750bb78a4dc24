#pragma once
// Iteration callbacks: called once before the first step (record 0) and after each step. A
// callback may read the problem (its variables are x_k), change term weights and Hessian shifts
// for the next iteration (the paper's lambda schedule), and decide whether to go on.

#include <functional>
#include <vector>

#include "optim/iteration_record.h"

namespace sa {

class Problem;

enum class CallbackResult {
    kContinue,
    kStopSuccess,  ///< the caller's convergence test is met: stop, report success
    kAbort,        ///< stop, report that the caller aborted
};

struct IterationContext {
    const IterationRecord& record;
    Problem& problem;
    /// Unweighted value of each term at x_k.
    const std::vector<double>& term_values;
};

using IterationCallback = std::function<CallbackResult(const IterationContext&)>;

}  // namespace sa
