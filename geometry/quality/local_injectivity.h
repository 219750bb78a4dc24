#pragma once
// Where a map with no inverted simplex still folds: it wraps more than once around an interior
// vertex (triangles) or an interior edge (tetrahedra), a branch point.
//
// Positive orientation of every simplex does not make a map locally injective. Around an
// interior vertex of a triangle mesh the image angles of its triangles sum to 2 pi k for a whole
// k; k = 2 is a branch point (the vertex's star covers its image twice, every triangle positive).
// A region whose fixed outer vertices make the boundary turn twice (turning number 2) can only be
// filled that way or with an inverted triangle. Around an interior edge of a tetrahedral mesh the
// dihedral angles of its tetrahedra sum to 2 pi k, and with every tetrahedron positive the map is
// locally injective exactly when every such k is 1 (the link of a vertex, a sphere, then covers
// its image once). The checks assume no inverted or degenerate simplex (those are counted apart).

#include <Eigen/Core>
#include <array>
#include <vector>

#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/rest_frames.h"

namespace sa {

/// Interior vertices of a triangle mesh mapped to the plane (`positions`, #V x 2) whose image
/// angles do not sum to 2 pi (sorted).
std::vector<Index> branched_vertices(const SimplicialMesh& mesh, const MeshTopology& topology,
                                     const Eigen::MatrixXd& positions);

/// Interior edges of a tetrahedral mesh mapped to space (`positions`, #V x 3), as indices into
/// topology.edges, whose tetrahedra's image dihedral angles do not sum to 2 pi (sorted).
std::vector<Index> branched_edges(const SimplicialMesh& mesh, const MeshTopology& topology,
                                  const Eigen::MatrixXd& positions);

/// The edges of a tetrahedral mesh as wrapped_simplices<3> reads them: each tetrahedron's six
/// edges (local vertex pairs 01 02 03 12 13 23) as indices into topology.edges, and per edge
/// whether it lies on a boundary facet. The same for every map of the mesh: computed once where
/// many maps are tested (an iteration's every iterate), it saves each test the edge searches.
struct TetEdges {
    std::vector<std::array<Index, 6>> of_tet;
    std::vector<unsigned char> on_boundary;
};
TetEdges tet_edges(const SimplicialMesh& mesh, const MeshTopology& topology);

/// The simplices around the wraps of a map given by its linear parts `A` (one per simplex of
/// `mesh`, in the frames `frames`): the stars of the interior vertices (D = 2) or edges (D = 3)
/// whose simplices are all positive in the map and whose angles sum to 2 pi k with k != 1
/// (sorted). The map may have inverted simplices elsewhere; stars with one are not looked at.
/// A map with wraps is not locally injective however its simplices are oriented, and no motion
/// that keeps every simplex positive removes one: it is as far from valid as a map with those
/// simplices inverted. `edges` (D = 3; tet_edges() of this mesh), when given, is used instead of
/// computing it.
template <int D>
std::vector<Index> wrapped_simplices(const SimplicialMesh& mesh, const MeshTopology& topology,
                                     const RestFrames<D>& frames, const std::vector<Mat<D>>& A,
                                     const TetEdges* edges = nullptr);

}  // namespace sa
