#pragma once
// A hexahedral mesh, in the layout of VTK_HEXAHEDRON and Medit's `Hexahedra`:
//
//   positions  #V x 3
//   hexes      #H x 8, 0-based vertex indices: the bottom face 0 1 2 3, then the top face 4 5 6 7
//              with corner 4 above 0, 5 above 1, ...; in a positively oriented hex the bottom
//              face turns counter-clockwise seen from the top. The unit cube is
//              (0,0,0) (1,0,0) (1,1,0) (0,1,0) (0,0,1) (1,0,1) (1,1,1) (0,1,1).
//
// Corner c's three edges (kHexCornerEdges[c]) go to its neighbours in the order that makes their
// determinant positive on the unit cube: the corner Jacobians of the hex-meshing literature
// (Knupp's scaled Jacobian, as in Verdict).

#include <Eigen/Core>
#include <array>

#include "optim/types.h"

namespace sa {

struct HexMesh {
    Eigen::MatrixXd positions;
    Eigen::MatrixXi hexes;

    Index num_vertices() const { return static_cast<Index>(positions.rows()); }
    Index num_hexes() const { return static_cast<Index>(hexes.rows()); }
};

/// Per corner: its three neighbours, in positive order.
inline constexpr std::array<std::array<int, 3>, 8> kHexCornerEdges = {
    {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}}};

/// The six faces, each turning counter-clockwise seen from outside the hex.
inline constexpr std::array<std::array<int, 4>, 6> kHexFaces = {
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};

/// Six tetrahedra around the diagonal 0-6, positively oriented on a positive hex: their volumes
/// add up to the hex's when its faces are planar.
inline constexpr std::array<std::array<int, 4>, 6> kHexTetrahedra = {
    {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}}};

}  // namespace sa
