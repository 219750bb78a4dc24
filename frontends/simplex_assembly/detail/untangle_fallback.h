#pragma once
// The last resort of a run that ends without a valid map. Internal to the mesh driver
// (frontends/simplex_assembly/map_solve.h).
//
// Simplex Assembly can fail where a valid map exists: its barrier E_C = e^{s d} must be finite at
// the start and its assembly must hold every simplex whose vertices are handles at its data,
// which a fixed boundary with distorted boundary simplices makes impossible (the full solve of
// tlc/armadillo-598 stalled at lambda = 1e16 with E~_assembly 0.035-0.055 in every variant,
// docs/measurements.md), and a region whose outer vertices are fixed may have no valid map at all.
// When the result still has inverted or degenerate simplices and time is left, the map is
// untangled in vertex variables (untangle.h) from whichever of the initial map (handles at their
// targets) and the result has fewer bad simplices, then the vertex stage lowers E_C where it can
// (vertex_stage.h; not with options.until_valid). The new map replaces the result when it has
// fewer inverted and degenerate simplices; the caller verifies it.

#include <string>

#include "frontends/simplex_assembly/detail/prepared_problem.h"
#include "frontends/simplex_assembly/untangle.h"
#include "optim/time_budget.h"

namespace sa {

/// untangle() on the prepared problem from `start` (normalized, #V x D): the handles and the
/// anchored simplices' vertices fixed, the options' projection, solver, threads and time left.
/// It stops at the first untangled iterate with options.until_valid; otherwise at the first one
/// that no simplex with a free vertex puts beyond the barrier's exponent cap (so that the vertex
/// stage can take over), or at its own convergence when the handles force such simplices
/// (tlc/armadillo-598).
template <int D>
UntangleResult untangle_prepared(PreparedProblem<D>& prepared,
                                 const SimplexAssemblyOptions& options, const TimeBudget& budget,
                                 const Eigen::MatrixXd& start, const Logger& logger);

/// Adds its record (Stage::kFallback) to result.stages, then the vertex stage's when that ran;
/// returns true when result.positions was replaced.
template <int D>
bool untangle_fallback(PreparedProblem<D>& prepared, const SimplexAssemblyOptions& options,
                       const TimeBudget& budget, const SimplexAssemblyObserver& observer,
                       SimplexAssemblyResult& result);

}  // namespace sa
