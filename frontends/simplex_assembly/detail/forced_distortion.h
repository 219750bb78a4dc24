#pragma once
// Simplices whose shape the handles alone decide, and whose barrier the A-variable assembly cannot
// hold there. Internal to the mesh driver (frontends/simplex_assembly/map_solve.h).
//
// When every vertex of a simplex is a handle, an assembled map has that simplex's linear part A
// at its data value (the handles' targets). At A the barrier's gradient is e^{s d} s grad d, and
// the penalty lambda E~_assembly holds A there only if lambda is of the order of e^{s d} or
// more: with s d above ln(lambda_max) no lambda of the schedule does, and the full solve stalls
// with E~_assembly > 0 (above s d = 709.8, e^{s d} itself overflowed before barrier.h's cap).
// A fixed boundary whose boundary simplices are that distorted does this:
// ../shared/data/tlc/armadillo-598 has 1,904 simplices whose four vertices are handles, 192 of
// them beyond ln(1e16) (up to d = 2.6e6), and its full solve stalled at lambda = 1e16 with
// E~_assembly 0.035-0.055 in every variant; tlc/stgc-3d has one, and its full solve "converges
// at lambda_max" with E~_assembly 2.2e-5 (docs/measurements.md). The auto mode sends such problems
// to the submesh mode, whose start untangles in vertex variables (untangle.h), where these
// simplices are constants.

#include <vector>

#include "frontends/simplex_assembly/detail/prepared_problem.h"

namespace sa {

/// Simplices with every vertex a handle, not inverted, whose barrier exponent s d at the handles'
/// targets is at least `exponent` (ln(options.lambda_max) by default).
template <int D>
std::vector<Index> barrier_forced_simplices(const PreparedProblem<D>& p,
                                            const SimplexAssemblyOptions& options,
                                            double exponent = -1.0);

/// Simplices with a vertex that is not a handle whose barrier exponent s d at `positions`
/// (normalized, #V x D) is beyond barrier.h's cap: while one is there, E_C cannot rank the others
/// (its value swamps theirs) and the vertex stage does not run (vertex_stage.h).
template <int D>
Index simplices_beyond_barrier_cap(const PreparedProblem<D>& p, const Eigen::MatrixXd& positions);

}  // namespace sa
