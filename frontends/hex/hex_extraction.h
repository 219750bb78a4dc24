#pragma once
// Extraction of a hexahedral mesh from a quantized PolyCube map (issue 48): every unit cell of the
// integer grid inside the PolyCube becomes a hex, whose corners are mapped back to the rest mesh
// through the inverse of the piecewise-linear map.
//
//   grid   #V x 3, the PolyCube map of the tetrahedra in grid units: its planes at integers
//          (plane_quantization.h), injective;
//   rest   #V x 3, the rest positions (any frame and units): where the hexes are built.
//
// Point location: each tetrahedron of the grid-space mesh visits the grid points and cell centres
// in its bounding box and keeps those inside it up to a tolerance (barycentric coordinates
// >= -1e-9); a point in several (on a shared face, edge or vertex) takes the tetrahedron where it
// is deepest. A cell is inside when its centre is (centres never lie on a plane, so never on
// the boundary). A corner maps to the barycentric combination of its tetrahedron's rest vertices
// (coordinates clamped at 0): grid points on a chart's plane lie on a boundary facet and land on
// the rest boundary. Corners shared by cells are one vertex.

#include <Eigen/Core>

#include "geometry/mesh/hex_mesh.h"

namespace sa {

struct HexExtraction {
    HexMesh mesh;  ///< in `rest`'s units; hexes in increasing (i, j, k) of their cell
    Eigen::MatrixXi grid_points;  ///< #V x 3, each vertex's grid point
    /// Cells whose centre was located but a corner not (a map that is not injective or not on
    /// its planes); such cells are left out.
    Index cells_with_missing_corners = 0;
};

/// The hexes of the map `grid` of `tets` (#T x 4), built on `rest` as described above. Throws
/// InvalidArgumentError on mismatched shapes or a grid coordinate beyond +-2^19.
HexExtraction extract_hexes(const Eigen::MatrixXi& tets, const Eigen::MatrixXd& grid,
                            const Eigen::MatrixXd& rest);

}  // namespace sa
