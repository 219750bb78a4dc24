#pragma once
// The descent mode of the mesh driver (SolveMode::kDescent): a start that cannot fold, kept
// valid. Newton on the vertex positions (the vertex stage, vertex_stage.h) of mu E_m + E_C from
// an initial map that is already inversion-free, without disassembly or assembly. The barrier and
// the largest feasible step keep every iterate valid, so the result has no inverted or degenerate
// simplex whenever the start has none: the fallback of a parameterization whose requested start
// folds beyond repair (SLIM-style methods start the same way, from a Tutte map).
//
// Two continuations make the start usable whatever its distortion:
//  - the exponent: E_C = e^{s d} (Eq. 10) of a start with d in the hundreds (Tutte maps of meshes
//    with sliver triangles) overflows the Hessian's range (e^{125} at d = 125: factorization
//    fails). Every round below is a run of the vertex stage with its exponent continuation
//    (vertex_stage.h: rounds at s_r = min(s, kExponentRange / (d_max - d_min)), raised as the
//    spread of distortions falls, until s_r = s). Fu et al. 2015 note AMIPS's sensitivity to s on
//    highly distorted starts (the paper, section 5.1): this is the same exponent, raised gradually.
//  - the bound: a start over the bound K cannot enter the bounded barrier e^{s d} / (K - d).
//    The descent first runs unbounded; then, while d_max >= K, the bound loop (bound_rounds.h)
//    lowers d_max in rounds with the bound K_r = d_max + (d_max - 1) / 10 (room above the current
//    maximum so that the start is well inside the barrier), each a run of the vertex stage, and
//    the last round takes K. If d_max stops falling first (a round lowers d_max - 1 by less than
//    1%), the result is valid but over the bound, and says so. A bound at the identity's
//    distortion lowers d_max as far as the rounds go: the optimal bound from a valid start.
// A run whose result has degenerate simplices (the verification's relative rule) while its start
// had none is undone by the vertex stage and ends the descent: energies whose minimizers are not
// representable in doubles (conformal maps of long or nearly closed surfaces shrink parts by 1e14
// and more) cannot turn a valid start into a failed result.
//
// The start is the initial map with its handles at their targets, where they stay. A start with
// a simplex that is not positively oriented (det A <= 0), or a boundary angle sum of 2 pi or more
// under E_theta, is not run from: the trace records the vertex stage as
// VertexStageOutcome::kSkippedInfeasibleStart, with the counts as its figures. Without the
// built-in energy (builtin_energy = false) the descent is one run of the vertex stage on the
// problem's own energies: the rounds lower the built-in bound only.

#include <string>

#include "frontends/simplex_assembly/detail/prepared_problem.h"
#include "optim/time_budget.h"

namespace sa {

/// Fills result.positions (original units), result.descent_rounds, result.vertex_stage and the
/// vertex stage's records of result.stages.
template <int D>
void solve_descent(const PreparedProblem<D>& prepared, const SimplexAssemblyOptions& options,
                   const TimeBudget& budget, const SimplexAssemblyObserver& observer,
                   SimplexAssemblyResult& result);

/// The descent in a sentence: its rounds, Newton steps and exponents, or why it did not run.
std::string describe_descent(const SimplexAssemblyResult& result);

}  // namespace sa
