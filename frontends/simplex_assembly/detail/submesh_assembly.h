#pragma once
// The submesh strategy of section 4.4 ("Speedup"), and the choice between it and the full solve.
//
// Round l = 0, 1, ..., l_max:
//   1. positions: for l = 0 the start of submesh_start.h (the initial map, the paper's M^0, or an
//      accelerated ARAP or ASAP iterate from it, whichever has the fewest bad simplices); then
//      the result of the previous round (a round that repaired no region ends the rounds: the
//      next would solve the same regions from the same positions);
//   2. bad simplices: those the barrier rejects (inverted, at or over the bound, or so distorted
//      that e^{s d} is beyond the barrier's exponent cap, unless the start came from the
//      untangling) and degenerate ones (submesh_start.h's bad_simplices());
//      none: done;
//   3. regions: m rings of simplices around the bad ones (over shared vertices); regions that
//      share a vertex are merged, so each region is solved once and regions never move a vertex
//      another one uses;
//   4. each region is a mapping problem of its own: its vertices shared with simplices outside
//      it are fixed (with the original handles); it is solved by the full Simplex Assembly
//      (mode kFull), or in vertex variables (mode kDescent) when the start has no bad simplex
//      (the optimal bound's rounds: a verified map within its bounds, regions around the
//      simplices near them), and its result kept only if verified; a region that fails grows by two
//      rings and is solved again, up to m_max rings, unless the rings add nothing (the region is
//      its whole component: solved again, it would fail the same way). Regions that overlap after
//      growing conflict: the conflict graph is coloured and each colour's regions are solved side
//      by side with TBB.
// When options.max_time_seconds runs out, the start stops at its best iterate so far and no
// further colour or round is begun; the positions reached are the result.
// Results do not depend on the thread count: each region's solve is deterministic, regions of
// one colour share no vertex, and colours run in a fixed order. (With a time limit, where the run
// stops depends on the machine's speed.)

#include "frontends/simplex_assembly/detail/prepared_problem.h"

namespace sa {

/// The mode for `options.mode`: kDescent when asked; otherwise kFull or kSubmesh, resolving kAuto
/// by the mesh's size and its share of bad simplices in the initial map (over
/// options.auto_bad_share: kFull, unless every boundary vertex is a handle); kSubmesh whatever
/// those when the handles force the barrier beyond lambda_max (forced_distortion.h).
template <int D>
SolveMode choose_mode(const PreparedProblem<D>& prepared, const SimplexAssemblyOptions& options);

/// Fills result.positions (original units) and result.submesh.
template <int D>
void solve_submeshes(PreparedProblem<D>& prepared, const SimplexAssemblyOptions& options,
                     const TimeBudget& budget, const SimplexAssemblyObserver& observer,
                     SimplexAssemblyResult& result);

}  // namespace sa
