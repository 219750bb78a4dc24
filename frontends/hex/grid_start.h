#pragma once
// The start of the PolyCube on the grid (issue 48): a verified PolyCube map whose planes are
// moved to their quantized positions (plane_quantization.h), the rest of the mesh following.
//
// Per axis a, the displacement d (one value per vertex, in grid units) is harmonic over the
// PolyCube: it minimizes sum_T vol_T |grad_T d|^2, with the P1 gradients of the map's
// tetrahedra, subject to d = q_p - c_p / h on every vertex of a plane p of axis a. Each plane
// moves as a whole along its axis and the slabs between planes are stretched or squashed
// smoothly, in every direction, instead of by a per-axis piecewise-linear warp whose kinks
// fold the thin tetrahedra that a PolyCube has along its boundary (robustPolycube S3: 1,905
// folded). The start is x / h + d. Where quantization merged planes (a slab squashed to zero
// thickness) it folds; the solve on the grid untangles it.
//
// Cost: per axis, one sparse Cholesky factorization of the free vertices' system (CHOLMOD).

#include <Eigen/Core>
#include <array>
#include <vector>

#include "frontends/hex/plane_quantization.h"
#include "geometry/mesh/simplicial_mesh.h"

namespace sa {

/// The start described above, #V x 3 in grid units, from `map` (#V x 3, a PolyCube map of
/// `tets` (#T x 4) with no flat tetrahedron), each vertex's planes `plane_of_vertex` (per
/// axis, -1 for none; polycube_planes()), the planes' `coordinates` in `map` (per plane) and
/// their `quantization`. Throws InvalidArgumentError on mismatched sizes or a flat tetrahedron.
Eigen::MatrixXd grid_start(const Eigen::MatrixXi& tets, const Eigen::MatrixXd& map,
                           const std::vector<std::array<int, 3>>& plane_of_vertex,
                           const std::vector<double>& coordinates,
                           const PlaneQuantization& quantization);

}  // namespace sa
