#pragma once
// The submesh mode's start (round 0's positions) and its test for bad simplices. Internal to
// the mesh driver (frontends/simplex_assembly/map_solve.h).
//
// From the initial map with the handles at their targets, unless the regions of options.rings
// rings around its bad simplices hold no more simplices than the auto mode solves in full
// (options.auto_full_triangles / auto_full_tetrahedra): local defects, solved as they are.
// Otherwise:
//   1. the paper's M^0: each A_i projected as in the disassembly (Initialization), vertices by
//      Eq. 6 with the handles fixed;
//   2. from M^0, local/global iterations on Eq. 6's least squares Q
//   (geometry/maps/arap_local_step.h):
//      ARAP (rotations), or ASAP (similarities) when the disassembly projects to similarities.
//      They spread large handle motions through the mesh, which the initial map leaves to the
//      simplices next to the handles. Plain iteration creeps (rabbit of ../shared/data/deform,
//      with the disassembly's projection of A_i as the local step: 589 bad tetrahedra after 30
//      iterations, 89 after 400), so the iterates are Anderson-accelerated
//      (optim/anderson_acceleration.h); an accelerated point that raises Q is replaced by the plain
//      step (Q never increases along plain steps).
// Every iterate is measured; the one with the fewest bad simplices is kept, and among as few the
// later one (lower Q: ARAP's own distortion measure). The iterations stop after
// options.start_iterations, or when the fewest has not improved over the last quarter of that
// many, or (options.until_valid) at the first iterate without a bad simplex.
// The local/global iterations also stop once Q has converged (it fell by less than 1e-3 over
// the last 10 iterations): they would not change the map any more.
//   3. when bad simplices are left, Newton on the vertex positions of a regularized barrier that
//      needs no feasible start (untangle.h, untangle_fallback.h's untangle_prepared()), from the
//      best iterate so far, until no simplex is inverted (and, unless options.until_valid, none
//      with a free vertex is beyond the barrier's exponent cap, or the untangling converged);
//      kept when it has fewer bad simplices. Local/global iterations fit rotations or
//      similarities and cannot see which simplices are inverted: on a fixed boundary with a
//      large tangled region (../shared/data/tlc/armadillo-598) they never improve on M^0.
//      Not when the regions around the bad simplices have fewer variables (D^2 per simplex)
//      than the mesh's free vertex positions, the driver's untangling fallback is on and no
//      simplex is forced beyond the exponent cap: the rounds go first, and the fallback
//      untangles the whole mesh if they fail.

#include <optional>
#include <string>
#include <vector>

#include "frontends/simplex_assembly/detail/prepared_problem.h"
#include "frontends/simplex_assembly/stage_trace.h"
#include "optim/logger.h"

namespace sa {

struct SubmeshStart {
    Eigen::MatrixXd positions;    ///< #V x D, original units
    std::vector<Index> bad;       ///< its bad simplices
    StartChoice choice;           ///< which iterate
    bool recovered = false;       ///< from Eq. 6: every free vertex moved from the initial map
    int iterations = 0;           ///< local/global iterations run after M^0
    int rejected = 0;             ///< accelerated points replaced by plain steps
    bool untangled = false;       ///< from the untangling (untangle.h): see bad_simplices()
    int untangle_iterations = 0;  ///< Newton steps of the untangling start (untangle.h), if run
    std::optional<UntangleOutcome> untangle;                ///< how it ended, when it ran
    AssemblyStop untangle_stop = AssemblyStop::kConverged;  ///< the engine's reason
    double untangle_seconds = 0.0;
};

/// Simplices whose linear parts A (normalized map) the barrier rejects (inverted, at or over the
/// bound) and degenerate ones (the rule of map_quality()); unless `beyond_cap_allowed`, also those
/// with a free vertex whose e^{s d} is beyond the barrier's exponent cap (barrier.h): E_C cannot
/// rank them (they overflowed it before the cap existed), and region solves bring them back.
/// Simplices whose vertices are all handles are never bad for that reason: they are data.
/// And the stars of the map's wraps (wrapped_simplices(), local_injectivity.h): all positive but
/// not locally injective, so not valid either (an untangling that makes a fold positive by
/// wrapping it twice around an edge does not remove a bad simplex).
template <int D>
std::vector<Index> bad_simplices(const PreparedProblem<D>& p, const std::vector<Mat<D>>& A,
                                 bool beyond_cap_allowed = false);

/// Stops its iterations, keeping the best iterate so far, when `budget` runs out.
template <int D>
SubmeshStart submesh_start(PreparedProblem<D>& p, const SimplexAssemblyOptions& options,
                           const TimeBudget& budget, const Logger& logger = {});

}  // namespace sa
