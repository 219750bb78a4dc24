#pragma once
// A start that cannot fold, kept valid: Newton on the vertex positions (the vertex stage,
// vertex_stage.h) of mu E_m + E_C from an initial map that is already inversion-free, without
// disassembly or assembly. The barrier and the largest feasible step keep every iterate valid, so
// the result has no inverted or degenerate simplex whenever the start has none: the fallback of
// a parameterization whose requested start folds beyond repair (SLIM-style methods start the same
// way, from a Tutte map).
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

#include <string>
#include <vector>

#include "frontends/simplex_assembly/map_solve.h"

namespace sa {

/// One round of the descent: a round of the vertex stage's exponent continuation (or its single
/// run) at one bound.
struct DescentRound : ContinuationRound {
    double bound = kInfinity;  ///< the bound used
};

struct VertexDescentResult {
    /// positions, verification, success, message, times, vertex_stage (the last round's Newton
    /// summary); no assembly ran.
    SimplexAssemblyResult solve;
    std::vector<DescentRound> rounds;
    /// Every simplex of the start is positively oriented (det A > 0): the barrier is finite there.
    /// Degenerate simplices (by the verification's relative rule) may remain in the result.
    bool start_valid = false;
};

/// Every simplex of `problem.initial` must be positively oriented (otherwise nothing runs:
/// start_valid is false and the result is the start, reported as failed). Handles, anchors, E_m's
/// reference and the boundary barrier are as in run_simplex_assembly. Throws as
/// run_simplex_assembly on bad input.
VertexDescentResult run_vertex_descent(const MappingProblem& problem,
                                       const SimplexAssemblyOptions& options,
                                       const SimplexAssemblyObserver& observer = {});

}  // namespace sa
