#pragma once
// The boundary surface of a tetrahedral mesh, tied to the tetrahedra's facets.
//
// Facet k of a tetrahedron (v0, v1, v2, v3) is the triangle opposite v_k. Its corners, in
// ultimaille's order (the order of the .flags files of polycube_withHexEx and robustPolycube), are
// kTetFacetCorners[k]; for a positively oriented tetrahedron (det[v1 - v0, v2 - v0, v3 - v0] > 0)
// that winding's normal (b - a) x (c - a) points out of the tetrahedron, for a negatively
// oriented one into it. A tet facet is numbered 4 t + k.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "geometry/mesh/mesh_topology.h"

namespace sa {

inline constexpr int kTetFacetCorners[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

/// The sign of tetrahedron t's rest orientation: +1 when det[v1 - v0, v2 - v0, v3 - v0] > 0,
/// -1 otherwise (degenerate tetrahedra are rejected by validate_mesh()).
int tet_orientation(const SimplicialMesh& mesh, Index t);

/// The vertices of facet k of tetrahedron t, in ultimaille's winding.
std::array<Index, 3> tet_facet_vertices(const SimplicialMesh& mesh, Index t, int k);

/// The area vector of facet k of tetrahedron t at `positions` (#V x 3): half the cross product,
/// pointing out of the tetrahedron when `orientation` is its rest orientation (+1 or -1) and the
/// map keeps it.
Eigen::Vector3d tet_facet_area_vector(const Eigen::MatrixXd& positions, const SimplicialMesh& mesh,
                                      Index t, int k, int orientation);

struct TetBoundary {
    /// Boundary triangle b is tet facet tet_facet[b] = 4 t + k.
    std::vector<Index> tet_facet;
    /// #B x 3: the vertices of each boundary triangle, wound so that its normal points out of
    /// the mesh at rest (ultimaille's winding, reversed for negatively oriented tetrahedra).
    Eigen::MatrixXi triangles;
    /// Per tet facet (4 #T entries): its boundary triangle, or -1 for an interior facet.
    std::vector<Index> of_tet_facet;
    /// Per boundary triangle, per side i (the edge from corner i to corner (i + 1) % 3): the
    /// boundary triangle across it, or -1 when the edge has another number of boundary triangles
    /// than two (a non-manifold boundary edge).
    std::vector<std::array<Index, 3>> adjacent;
    /// Boundary edges (sorted vertex pairs, in lexicographic order).
    std::vector<std::array<Index, 2>> edges;
    /// Per vertex: on the boundary (in a boundary triangle).
    std::vector<unsigned char> on_boundary;

    Index size() const { return static_cast<Index>(tet_facet.size()); }
    Index tet(Index b) const { return tet_facet[b] / 4; }
    int facet(Index b) const { return static_cast<int>(tet_facet[b] % 4); }
};

/// The boundary of a tetrahedral mesh (simplices #T x 4).
TetBoundary tet_boundary(const SimplicialMesh& mesh, const MeshTopology& topology);

/// Outward area vectors (half cross products) of the boundary triangles at `positions` (#V x 3),
/// one row each (#B x 3).
Eigen::MatrixXd boundary_area_vectors(const TetBoundary& boundary,
                                      const Eigen::MatrixXd& positions);

/// The number of independent loops in a solid that no surface inside it spans (its first Betti
/// number: 1 for a solid torus or a cup with a handle, the genus for a handlebody, 0 for a ball,
/// with or without cavities), from its boundary, which must be a closed manifold surface (every
/// edge in two triangles): over a solid in space, b1 = (boundary components) - chi / 2, with chi =
/// V - E + F the boundary's Euler characteristic. Throws InvalidArgumentError for a boundary that
/// is not a closed manifold surface.
Index independent_loops(const TetBoundary& boundary);

}  // namespace sa
