#pragma once
// Loop subdivision of a triangle mesh through OpenMesh (each level splits every triangle in four
// and smooths; boundaries are kept as boundaries). Used to build large meshes from small ones.
// OpenMesh lives in the plugin libsa_openmesh.so, loaded on first use
// (geometry/io/openmesh_plugin.h): loop_subdivide throws Error naming the folders tried when it
// cannot be found.

#include "geometry/mesh/simplicial_mesh.h"

namespace sa {

/// `levels` rounds of Loop subdivision; throws InvalidArgumentError for tetrahedra or levels < 0,
/// InputError when OpenMesh cannot build the mesh (non-manifold input).
SimplicialMesh loop_subdivide(const SimplicialMesh& mesh, int levels);

}  // namespace sa
