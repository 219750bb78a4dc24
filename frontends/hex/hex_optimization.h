#pragma once
// Optimization of a hex mesh's vertex positions (issue 48), a problem of the optimizer
// (optim/problem.h) as a user would write one:
//
//   variables  per vertex 3: an inner vertex's position; a boundary vertex's motion on the input's
//              surface when the PolyCube's surface is given (HexBoundarySurface), fixed
//              otherwise;
//   energy     per hex, its eight corner tetrahedra (the corner and its three neighbours,
//              kHexCornerEdges; those whose four vertices are all fixed are constant and left out):
//              E = sum_corners exp(d(J_c)), d the 3D conformal distortion of the corner's edge
//              matrix J_c against the unit cube's corner (J = I): 1 for a right-angled corner of
//              equal edges, +inf when det J_c <= 0. The corner Jacobians stay positive (a
//              barrier, the line search keeps every step inside it) and the exponential pulls
//              hardest on the worst corners, which the scaled Jacobian's minimum measures. The
//              energy is SimplexEnergy<3> with the unbounded conformal barrier
//              (energies/simplex_energy.h), on the corner's vertex positions through
//              VertexSimplexEnergy (A = J, rest edges the identity).
//
// Sliding. A boundary vertex has a point on the PolyCube's surface in grid units (extraction's
// grid point). The axes of its boundary quads there say what it is: on one chart's plane (one
// axis) it moves in that plane, on a PolyCube edge (two axes) along the edge, at a PolyCube
// corner (three) not at all. It stays on the input's surface, and a PolyCube edge's vertices on
// the input's feature curve. Each round, Newton solves with every sliding vertex on the tangent
// plane (line) of the rest triangle its point is in (SubspacePointEnergy; its variables are its
// displacement in grid units through that triangle's map); then each moved vertex returns to the
// surface at the closest rest point of its plane (of its PolyCube edge) near where its grid point
// went (PolycubeSurface::closest): exact on a flat face, however the PolyCube map distorts it. The
// round's step is halved until no hex is inverted and the energy is lower.
//
// Rounds. exp(s d), s from E_C's continuation rule (energies/exponent_continuation.h): 20 over
// the corners' spread of distortions, at most 1, so that a corner left nearly flat by the
// untangling needs few Newton steps, and s rises to 1 as the spread falls. Rounds of at most 20
// Newton steps repeat until s = 1 and a round lowers the energy by less than 1e-4 of itself, or
// max_iterations steps in all. Without a surface the boundary is fixed and only the rounds remain.
//
// A mesh with inverted hexes has no finite energy: their corners are untangled first, by the
// regularized barrier of Garanzha et al. (frontends/simplex_assembly/untangle.h) on the corner
// tetrahedra with the boundary fixed. When an inverted hex is inverted only at corners whose four
// vertices are all on the boundary, or the untangling leaves one, the mesh is returned unchanged
// (ran = false).

#include <string>

#include "frontends/hex/polycube_surface.h"
#include "geometry/mesh/hex_mesh.h"
#include "optim/logger.h"
#include "optim/newton_summary.h"

namespace sa {

struct HexOptimizationOptions {
    int max_iterations = 100;     ///< Newton steps of the untangling, and of all the rounds
    double max_time = kInfinity;  ///< seconds
    int threads = 0;              ///< 0 = all cores
};

/// Where the boundary vertices slide: the quantized PolyCube's surface and each vertex's point
/// on it.
struct HexBoundarySurface {
    const PolycubeSurface* surface = nullptr;
    Eigen::MatrixXd grid_points;  ///< #V x 3, grid units (rows of inner vertices unused)
};

struct HexOptimization {
    HexMesh mesh;             ///< the optimized mesh (the input's when nothing ran)
    bool ran = false;         ///< false: no free vertex, or an inverted hex left after untangling
    bool untangled = false;   ///< inverted hexes at the start were untangled
    NewtonSummary newton;     ///< the last round's
    Index free_vertices = 0;  ///< inner vertices
    Index sliding_vertices = 0;  ///< boundary vertices on a plane or a PolyCube edge
    int rounds = 0;              ///< of Newton, each at its exponent scale
    Index newton_steps = 0;      ///< in all rounds
    std::string message;         ///< one sentence
};

/// Optimizes `mesh` as described above, its boundary sliding on `surface` when that is given
/// (`surface.grid_points` #V x 3; throws InvalidArgumentError otherwise); progress goes to
/// `logger`.
HexOptimization optimize_hex_mesh(const HexMesh& mesh, const HexOptimizationOptions& options,
                                  const Logger& logger = {},
                                  const HexBoundarySurface& surface = {});

}  // namespace sa
