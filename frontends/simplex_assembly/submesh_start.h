#pragma once
// The submesh mode's start (round 0's positions) and its test for bad simplices. Internal to
// frontends/simplex_assembly.
//
// From the initial map with the handles at their targets, unless the regions of options.rings
// rings around its bad simplices hold no more simplices than the auto mode solves in full
// (options.auto_full_triangles / auto_full_tetrahedra): local defects, solved as they are.
// Otherwise:
//   1. the paper's M^0: each A_i projected as in the disassembly (Initialization), vertices by
//      Eq. 6 with the handles fixed;
//   2. from M^0, local/global iterations on Eq. 6's least squares Q (geometry/arap_local_step.h):
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

#include <string>
#include <vector>

#include "frontends/simplex_assembly/prepared_problem.h"

namespace sa {

struct SubmeshStart {
    Eigen::MatrixXd positions;  ///< #V x D, original units
    std::vector<Index> bad;     ///< its bad simplices
    std::string description;    ///< which iterate: "initial map", "M^0 (Eq. 6)", ...
    bool recovered = false;     ///< from Eq. 6: every free vertex moved from the initial map
    int iterations = 0;         ///< local/global iterations run after M^0
    int rejected = 0;           ///< accelerated points replaced by plain steps
};

/// Simplices whose linear parts A (normalized map) the barrier rejects (inverted, at or over the
/// bound, or so distorted that E_C overflows) and degenerate ones (the rule of map_quality()).
template <int D>
std::vector<Index> bad_simplices(const PreparedProblem<D>& p, const std::vector<Mat<D>>& A);

/// Stops its iterations, keeping the best iterate so far, when `budget` runs out.
template <int D>
SubmeshStart submesh_start(PreparedProblem<D>& p, const SimplexAssemblyOptions& options,
                           const TimeBudget& budget);

}  // namespace sa
