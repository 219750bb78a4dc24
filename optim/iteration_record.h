#pragma once
// What one Newton iteration did. Record 0 describes the starting point; record k >= 1 the step
// from x_{k-1} to x_k. Fields that do not apply hold -1 (as in Ceres).

#include "optim/types.h"

namespace sa {

struct IterationRecord {
    int iteration = 0;
    double energy = 0.0;               ///< E(x_k), at the weights used for this step
    double energy_change = -1.0;       ///< E(x_{k-1}) - E(x_k), same weights
    double gradient_norm = -1.0;       ///< max |g_i| at x_{k-1}, over free variables
    double decrement = -1.0;           ///< predicted decrease -g.d / 2 of the Newton step d
    double step_length = -1.0;         ///< accepted alpha: x_k = x_{k-1} + alpha d
    double max_feasible_step = -1.0;   ///< smallest element max_step along d (+inf: none)
    int line_search_trials = -1;       ///< energy evaluations by the line search
    double regularization = -1.0;      ///< tau added to the diagonal (0: none needed)
    int factorizations = -1;           ///< numeric factorizations (1 + retries)
    Index projected_blocks = -1;       ///< element Hessians changed by the projection
    double iteration_time = 0.0;       ///< seconds spent on this iteration (callbacks excluded)
    double factorization_time = -1.0;  ///< seconds of it in numeric factorizations (retries too)
    double cumulative_time = 0.0;      ///< seconds since the solve started
};

}  // namespace sa
