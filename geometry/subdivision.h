#pragma once
// Loop subdivision of a triangle mesh through OpenMesh (each level splits every triangle in four
// and smooths; boundaries are kept as boundaries). Used to build large meshes from small ones.

#include "geometry/simplicial_mesh.h"

namespace sa {

/// `levels` rounds of Loop subdivision; throws InvalidArgumentError for tetrahedra or levels < 0,
/// InputError when OpenMesh cannot build the mesh (non-manifold input).
SimplicialMesh loop_subdivide(const SimplicialMesh& mesh, int levels);

}  // namespace sa
