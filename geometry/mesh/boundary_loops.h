#pragma once
// Boundary loops of a triangle mesh, and the checks a parameterization needs: a manifold surface
// with a boundary and genus 0 (a disk: one loop and V - E + F = 1; or with holes).

#include <string>
#include <vector>

#include "geometry/mesh/mesh_topology.h"

namespace sa {

/// Each boundary loop as its vertices in order, oriented like the triangles (each loop follows
/// the boundary edges in the direction the adjacent triangle traverses them). Loops are ordered
/// by their smallest vertex; each starts at its smallest vertex.
std::vector<std::vector<Index>> boundary_loops(const SimplicialMesh& mesh,
                                               const MeshTopology& topology);

/// Throws InputError naming `source` unless the triangle mesh is a topological disk: manifold
/// (checked by mesh_topology), one boundary loop, V - E + F = 1 (V: the vertices of triangles).
void require_disk(const SimplicialMesh& mesh, const MeshTopology& topology,
                  const std::string& source);

/// Throws InputError naming `source` unless the triangle mesh can lie in the plane: manifold,
/// connected (over shared edges), at least one boundary loop, genus 0 (V - E + F = 2 - loops: a
/// disk, an annulus, a disk with holes; V counts the vertices of triangles: others are allowed).
/// Returns the number of boundary loops.
Index require_planar_surface(const SimplicialMesh& mesh, const MeshTopology& topology,
                             const std::string& source);

}  // namespace sa
