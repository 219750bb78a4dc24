#pragma once
// The cube-cover start of a PolyCube map (issue 21; the kind of initial map the paper's 5.3 takes
// from Aigerman and Lipman 2013): each coordinate axis a separately, one sparse least-squares
// solve in which every chart of axis a has a single coordinate (shared by all of its vertices:
// the chart is planar and orthogonal to a) and everything else follows the mesh:
//
//     minimize  sum_T vol_T |grad_T x - e_a|^2   over x (one value per vertex),
//     subject to x_v = c_k for every vertex v of a chart k of axis a,
//
// i.e. the Dirichlet energy of x - p_a (p the rest positions) with the P1 gradients of the rest
// tetrahedra: the interior follows the cotangent Laplacian, L x = L p_a away from the charts (and
// the PolyCube edges, below).
// Charts of one axis that share a vertex share their coordinate. The energy does not see a
// translation along a; the solution is shifted so that its volume-weighted mean equals that of
// p_a in each connected component.
//
// A least-squares fit does not keep PolyCube edges (polycube_planes.h) in order: two planes whose
// rest positions are close can swap, and an edge between them then folds its tetrahedra in a
// way no motion of its vertices undoes. So every edge whose corners' planes come out of rest
// order or closer than half its rest extent has the two planes tied at that distance, and the
// axis is solved again (an active set that only grows, at most 20 solves per axis).
//
// The same holds for the vertices inside an edge: on the line where its two planes meet each has
// one degree of freedom, so a vertex placed beyond its neighbour along the line could only get
// back past it by collapsing the mesh edge between them, which no inversion-free path does (an
// edge that is U-shaped at rest, or one that turns back at a corner). So, once the planes
// are placed, the vertices of every edge along the axis are set in their order between its
// corners, spaced by rest arc length, and the axis is solved once more with the planes and those
// vertices held. The map may still fold (a chart pulled behind another, thin parts flattened):
// Simplex Assembly, or the untangling on the planes, repairs it.
//
// Cost: per axis, one factorization of a #V-sized SPD matrix (CHOLMOD supernodal, AMD ordering,
// through optim/linear_solver.h), one more per pass that ties planes, and one for the edges.

#include <Eigen/Core>
#include <vector>

#include "frontends/polycube/polycube_labeling.h"

namespace sa {

struct CubeCover {
    /// #V x 3 positions.
    Eigen::MatrixXd positions;
    /// Per chart (PolycubeCharts numbering): its coordinate along its axis.
    std::vector<double> chart_coordinate;
    /// PolyCube edges between two corners (polycube_planes.h), and of those: edges whose corners
    /// share a plane (no PolyCube has them), edges whose corners' planes the least-squares fit
    /// put out of rest order or closer than half their rest extent (tied at that distance and
    /// solved again), and edges still shorter than a quarter of their rest extent at the end.
    Index edge_orders = 0, collapsed_edges = 0, lengthened_edges = 0, unordered_edges = 0;
    /// The minimized energy per axis, sum_T vol_T |grad_T x - e_a|^2 (0 for the identity).
    Eigen::Vector3d energy = Eigen::Vector3d::Zero();
};

/// The cube-cover map of `mesh` (tetrahedra, rest positions) for the charts of a labelling of its
/// boundary. Throws InvalidArgumentError when `charts` does not belong to `boundary`.
CubeCover cube_cover_map(const SimplicialMesh& mesh, const TetBoundary& boundary,
                         const PolycubeCharts& charts);

}  // namespace sa
