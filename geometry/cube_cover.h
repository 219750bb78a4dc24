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
// tetrahedra: the interior follows the cotangent Laplacian, L x = L p_a away from the charts.
// Charts of one axis that share a vertex share their coordinate. The energy does not see a
// translation along a; the solution is shifted so that its volume-weighted mean equals that of
// p_a in each connected component. The map may fold (a chart pulled behind another, thin parts
// flattened): Simplex Assembly repairs it.
//
// Cost: three factorizations of a #V-sized SPD matrix (CHOLMOD supernodal, AMD ordering, one
// factorization each, through optim/linear_solver.h).

#include <Eigen/Core>
#include <vector>

#include "geometry/polycube_labeling.h"

namespace sa {

struct CubeCover {
    /// #V x 3 positions.
    Eigen::MatrixXd positions;
    /// Per chart (PolycubeCharts numbering): its coordinate along its axis.
    std::vector<double> chart_coordinate;
    /// The minimized energy per axis, sum_T vol_T |grad_T x - e_a|^2 (0 for the identity).
    Eigen::Vector3d energy = Eigen::Vector3d::Zero();
};

/// The cube-cover map of `mesh` (tetrahedra, rest positions) for the charts of a labelling of its
/// boundary. Throws InvalidArgumentError when `charts` does not belong to `boundary`.
CubeCover cube_cover_map(const SimplicialMesh& mesh, const TetBoundary& boundary,
                         const PolycubeCharts& charts);

}  // namespace sa
