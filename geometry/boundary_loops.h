#pragma once
// Boundary loops of a triangle mesh, and the checks a parameterization needs: a manifold surface
// with exactly one boundary loop and the Euler characteristic of a disk (V - E + F = 1).

#include <string>
#include <vector>

#include "geometry/mesh_topology.h"

namespace sa {

/// Each boundary loop as its vertices in order, oriented like the triangles (each loop follows
/// the boundary edges in the direction the adjacent triangle traverses them). Loops are ordered
/// by their smallest vertex; each starts at its smallest vertex.
std::vector<std::vector<Index>> boundary_loops(const SimplicialMesh& mesh,
                                               const MeshTopology& topology);

/// Throws InputError naming `source` unless the triangle mesh is a topological disk: manifold
/// (checked by mesh_topology), one boundary loop, V - E + F = 1, every vertex used.
void require_disk(const SimplicialMesh& mesh, const MeshTopology& topology,
                  const std::string& source);

}  // namespace sa
