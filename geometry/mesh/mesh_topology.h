#pragma once
// Adjacency of a simplicial mesh: facets shared by two simplices, boundary facets, edges,
// the simplices around each vertex, boundary and unused vertices.
//
// A facet is a simplex's face opposite one of its vertices: an edge of a triangle, a triangle of
// a tetrahedron. A facet shared by more than two simplices makes the mesh non-manifold: rejected.

#include <array>
#include <string>
#include <vector>

#include "geometry/mesh/simplicial_mesh.h"

namespace sa {

struct InteriorFacet {
    std::array<Index, 2> simplex;   ///< the two simplices sharing it
    std::array<int, 2> opposite;    ///< in each, the local index of the vertex not on the facet
    std::array<Index, 3> vertices;  ///< the facet's vertices (the first d are used), sorted
};

struct BoundaryFacet {
    Index simplex;
    int opposite;
    std::array<Index, 3> vertices;  ///< the first d are used, sorted
};

struct MeshTopology {
    int dimension = 0;  ///< d
    std::vector<InteriorFacet> interior_facets;
    std::vector<BoundaryFacet> boundary_facets;
    std::vector<std::array<Index, 2>> edges;  ///< unique, each sorted, in lexicographic order
    /// Simplices around vertex v: simplices_of_vertex[vertex_begin[v] .. vertex_begin[v + 1]).
    std::vector<Index> vertex_begin;
    std::vector<Index> simplices_of_vertex;
    /// Neighbour of simplex s across the facet opposite local vertex k: neighbour[s * (d+1) + k],
    /// -1 on the boundary.
    std::vector<Index> neighbour;
    std::vector<unsigned char> boundary_vertex;
    std::vector<unsigned char> used_vertex;  ///< belongs to at least one simplex

    Index neighbour_of(Index s, int k) const {
        return neighbour[std::size_t(s) * (dimension + 1) + k];
    }
    /// Connected components over shared facets: a component number per simplex, and the count.
    std::vector<Index> simplex_components(Index* count) const;
};

/// The vertices where the mesh is pinched: their simplices do not form one piece through the
/// facets that contain the vertex (a bowtie's middle vertex, two solids touching at a vertex),
/// in increasing order. Such a vertex has no single disk (ball) of simplices around it.
/// `first_pieces`, when given, receives the number of pieces at the first one.
std::vector<Index> pinched_vertices(const SimplicialMesh& mesh, const MeshTopology& topology,
                                    int* first_pieces = nullptr);

/// Throws InputError "SOURCE: pinched at vertex V: its triangles (tetrahedra) form N pieces that
/// share no edge (face) through it (the only one | K more such vertices); NEEDS" when
/// pinched_vertices() finds one.
void require_no_pinched_vertex(const SimplicialMesh& mesh, const MeshTopology& topology,
                               const std::string& source, const std::string& needs);

/// Builds the adjacency of `mesh`. Throws InputError naming `source` and the facet when a facet is
/// shared by more than two simplices, or, for triangles in space, when two triangles sharing an
/// edge are oriented inconsistently.
MeshTopology mesh_topology(const SimplicialMesh& mesh, const std::string& source);

}  // namespace sa
