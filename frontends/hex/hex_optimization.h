#pragma once
// Optimization of a hex mesh's vertex positions (issue 48), a problem of the optimizer
// (optim/problem.h) as a user would write one:
//
//   variables  the positions of the vertices that are not on the boundary (3 each); the
//              boundary vertices are fixed, so the boundary stays on the input's surface
//              exactly where extraction put it;
//   energy     per hex, its eight corner tetrahedra (the corner and its three neighbours,
//              kHexCornerEdges; those with all four vertices fixed are constant and left out): E =
//              sum_corners exp(d(J_c)), d the 3D conformal distortion of the corner's edge matrix
//              J_c against the unit cube's corner (J = I): 1 for a right-angled corner of equal
//              edges, +inf when det J_c <= 0. The corner Jacobians stay positive (a barrier, the
//              line search keeps every step inside it) and the exponential pulls hardest on the
//              worst corners, which the scaled Jacobian's minimum measures. The energy is
//              SimplexEnergy<3> with the unbounded conformal barrier (energies/simplex_energy.h),
//              on the corner's vertex positions through VertexSimplexEnergy (A = J, rest edges the
//              identity).
//
// A mesh with inverted hexes has no finite energy: their corners are untangled first, by the
// regularized barrier of Garanzha et al. (frontends/simplex_assembly/untangle.h) on the corner
// tetrahedra with the same boundary fixed. When an inverted hex is inverted only at corners
// whose four vertices are all on the boundary (nothing can move them), or the untangling leaves
// one, the mesh is returned unchanged (ran = false).

#include <string>

#include "geometry/mesh/hex_mesh.h"
#include "optim/logger.h"
#include "optim/newton_summary.h"

namespace sa {

struct HexOptimizationOptions {
    int max_iterations = 100;     ///< Newton steps of the untangling, and of the optimization
    double max_time = kInfinity;  ///< seconds
    int threads = 0;              ///< 0 = all cores
};

struct HexOptimization {
    HexMesh mesh;            ///< the optimized mesh (the input's when nothing ran)
    bool ran = false;        ///< false: no free vertex, or an inverted hex left after untangling
    bool untangled = false;  ///< inverted hexes at the start were untangled
    NewtonSummary newton;
    Index free_vertices = 0;
    std::string message;  ///< one sentence
};

/// Optimizes `mesh` as described above; progress goes to `logger`.
HexOptimization optimize_hex_mesh(const HexMesh& mesh, const HexOptimizationOptions& options,
                                  const Logger& logger = {});

}  // namespace sa
