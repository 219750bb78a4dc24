#pragma once
// OpenMesh traits with double-precision points and normals (OpenMesh's defaults are floats), for
// the code that builds OpenMesh meshes from ours (reading files, subdivision).

#include <OpenMesh/Core/Mesh/Traits.hh>

namespace sa {

struct OpenMeshDoubleTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
};

}  // namespace sa
