#pragma once
// The combinatorics of seamless parameterization (the paper's 5.2, "Global seamless
// parameterizations"): the matching of a cross field across each interior edge, a cut graph that
// opens the surface into a disk through given vertices (the singularities), and the cut mesh.
//
//   cross_field_matchings   per interior facet (topology.interior_facets order) the k in
//                           {0, 1, 2, 3} such that i^k r_fg u_f is the direction of g's cross
//                           closest to the transported u_f (r_fg as in cross_field.h): the
//                           rotation R_e of Eq. 11 is by k quarter turns.
//   cut_graph               1 per interior facet that is cut: the edges not crossed by a
//                           breadth-first dual spanning tree of the faces, together with the
//                           boundary, pruned of dangling edges that do not end at a `through`
//                           vertex; the boundary edges are then left out. Cutting along it leaves
//                           a topological disk whose boundary passes through every `through`
//                           vertex (for a connected surface).
//   cut_along               splits every vertex on the cut into one copy per wedge of faces
//                           between cut edges.

#include <vector>

#include "geometry/mesh/mesh_topology.h"

namespace sa {

std::vector<int> cross_field_matchings(const SimplicialMesh& mesh, const MeshTopology& topology,
                                       const Eigen::MatrixXd& directions);

std::vector<unsigned char> cut_graph(const SimplicialMesh& mesh, const MeshTopology& topology,
                                     const std::vector<Index>& through);

struct CutMesh {
    SimplicialMesh mesh;                 ///< the same faces on the split vertices
    std::vector<Index> original_vertex;  ///< per vertex of `mesh`, the vertex it copies
};

CutMesh cut_along(const SimplicialMesh& mesh, const MeshTopology& topology,
                  const std::vector<unsigned char>& cut);

}  // namespace sa
