#pragma once
// The tetrahedra around each boundary edge and boundary vertex of a tetrahedral mesh: where the
// 3D boundary-angle barriers (frontends/polycube/tet_angle_barriers.h) sum their angles,
//   theta_e = sum of the dihedral angles at boundary edge e of the tetrahedra around it (< 2 pi),
//   theta_v = sum of the solid angles at boundary vertex v of the tetrahedra around it (< 4 pi).
// Each tetrahedron's other vertices are listed in the order whose rest orientation is positive,
// so that a map that inverts a tetrahedron counts its angle negatively.
//
// The tetrahedra around an edge (vertex) are grouped by the facets through the edge (vertex) they
// share: on a manifold boundary one group per edge (vertex); a non-manifold one gets a group per
// sheet, each with its own sum.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "geometry/mesh/tet_boundary.h"

namespace sa {

struct BoundaryEdgeFan {
    std::array<Index, 2> edge;                 ///< p, q
    std::vector<Index> tets;                   ///< tetrahedra around it
    std::vector<std::array<Index, 2>> others;  ///< per tet (r, s): det[q - p, r - p, s - p] > 0
    /// The distinct vertices of `others` in order of first appearance (the ring).
    std::vector<Index> ring;
};

struct BoundaryVertexStar {
    Index vertex;
    std::vector<Index> tets;
    std::vector<std::array<Index, 3>> others;  ///< per tet (a, b, c): det[a - v, b - v, c - v] > 0
    std::vector<Index> ring;                   ///< the distinct vertices of `others`
};

/// One fan per boundary edge (per sheet at a non-manifold edge), in the order of boundary.edges.
std::vector<BoundaryEdgeFan> boundary_edge_fans(const SimplicialMesh& mesh,
                                                const MeshTopology& topology,
                                                const TetBoundary& boundary);

/// One star per boundary vertex (per sheet at a non-manifold vertex), by increasing vertex.
std::vector<BoundaryVertexStar> boundary_vertex_stars(const SimplicialMesh& mesh,
                                                      const MeshTopology& topology,
                                                      const TetBoundary& boundary);

}  // namespace sa
