#pragma once
// The tagged simplex set Omega_s of section 4.3: for each edge of the Steiner tree, one simplex
// containing that edge. r-SA gives translation variables T_p only to these simplices. A simplex
// already tagged for another tree edge is reused when it contains the edge, so that |Omega_s|
// stays small.

#include <vector>

#include "frontends/simplex_assembly/steiner_tree.h"
#include "geometry/mesh/mesh_topology.h"

namespace sa {

/// The tagged simplex of each tree edge (same order as `tree_edges`).
std::vector<Index> tag_simplices(const SimplicialMesh& mesh, const MeshTopology& topology,
                                 const std::vector<GraphEdge>& tree_edges);

/// The simplices that contain both vertices a and b (ascending).
std::vector<Index> simplices_with_edge(const SimplicialMesh& mesh, const MeshTopology& topology,
                                       Index a, Index b);

}  // namespace sa
