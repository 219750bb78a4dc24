#pragma once
// Discrete branch points of a planar map of a triangle mesh, and their removal by composing the
// map with a conformal map of the plane.
//
// A fold of a free-boundary conformal start (LSCM, harmonic) can be a discrete branch point: the
// map behaves like w0 + a (z - z0)^2 around it, so that the image of any loop around the fold
// turns twice (its turning number, the tangent's winding, is 2 instead of 1; more generally
// tau). A map that keeps the positions of such a loop must fold or branch inside it, however
// large the loop: no submesh with fixed outer vertices can repair it, only a change of the map
// out to the free boundary of the mesh. When the fold sits where the start's conformal factor
// collapses (an LSCM start's |det A| can fall to 1e-7 of its median on a long protrusion), the
// paper's submesh strategy stops at such folds.
//
// Composition removes them: with w_k the image of fold k and tau_k its turning number,
//     G(w) = integral of prod_k (w - w_k)^(-(tau_k - 1) / tau_k) dw
// is conformal and single-valued on the image of every loop that avoids the folds, and G o f has
// no branch point at any fold: near fold k, f - w_k ~ (z - z_k)^tau_k, so (G o f)' = G'(f) f' ~
// (z - z_k)^(1 - tau_k) (z - z_k)^(tau_k - 1) is nonzero. Away from the folds G o f has the
// distortion of f (G is conformal), so the folds become small defects that loops of a few rings
// repair. G o f is evaluated at the vertices by integrating G' along a spanning tree of the edges
// grown from the vertex farthest from every w_k (Simpson's rule, the argument of each w - w_k
// followed continuously), so that the tree's branches meet, and any inconsistency stays, next to
// the folds.
//
// Folds whose loops turn once are local (the regions repair them); folds that turn 0 or fewer
// times are left alone (none was seen in practice).

#include <Eigen/Core>
#include <vector>

#include "geometry/mesh/mesh_topology.h"

namespace sa {

/// The turning number of the closed polygon `loop` (vertex indices into `positions`, #V x 2):
/// the sum of its exterior angles over 2 pi. Repeated points are skipped.
double turning_number(const std::vector<Index>& loop, const Eigen::MatrixXd& positions);

/// How many times the closed polygon `loop` winds around `point`.
double winding_number(const std::vector<Index>& loop, const Eigen::MatrixXd& positions,
                      const Eigen::Vector2d& point);

/// The boundary loops of a set of triangles `region` (sorted), each oriented like the triangles.
/// Empty when a vertex has two outgoing boundary edges (the region is pinched there).
std::vector<std::vector<Index>> region_boundary_loops(const SimplicialMesh& mesh,
                                                      const std::vector<Index>& region);

/// Folds of `positions` (#V x 2, a map of the triangle mesh to the plane) that no region with
/// fixed outer vertices can repair: among the regions of `rings` rings around the `bad` triangles
/// (merged where they share a vertex, holes filled), those whose boundary loop turns a whole
/// number of times other than once (regions with several boundary loops are not counted).
Index count_unrepairable_folds(const SimplicialMesh& mesh, const MeshTopology& topology,
                               const Eigen::MatrixXd& positions, const std::vector<Index>& bad,
                               int rings);

struct BranchPoint {
    std::vector<Index> simplices;  ///< the bad triangles of the fold
    Eigen::Vector2d image;         ///< w_k: a point the loops around the fold wind tau times
    int turning = 1;               ///< tau >= 2
};

/// The branch points among `bad` (triangles of `positions`, #V x 2, a map of the triangle mesh to
/// the plane): the regions of `rings` rings around them (merged where they share a vertex, holes
/// filled) whose boundary loop turns tau >= 2 times.
std::vector<BranchPoint> find_branch_points(const SimplicialMesh& mesh,
                                            const MeshTopology& topology,
                                            const Eigen::MatrixXd& positions,
                                            const std::vector<Index>& bad, int rings);

/// G o f for the branch points `points` of f = `positions` (#V x 2), scaled and translated to f's
/// bounding box; vertices in no triangle keep their positions.
Eigen::MatrixXd remove_branch_points(const SimplicialMesh& mesh, const MeshTopology& topology,
                                     const Eigen::MatrixXd& positions,
                                     const std::vector<BranchPoint>& points);

}  // namespace sa
