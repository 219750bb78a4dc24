#pragma once
// PLY and STL triangle meshes, read through OpenMesh (ASCII and binary). OpenMesh lives in the
// plugin libsa_openmesh.so, loaded on first use (geometry/openmesh_plugin.h): these functions
// throw Error naming the folders tried when it cannot be found.
//
// OpenMesh builds a halfedge mesh: it detaches faces that would make the mesh non-manifold
// (a "complex edge" or "complex vertex": it re-adds them on copies of their vertices) and drops
// faces with repeated or out-of-range vertices, mostly without a message. Rather than return a
// mesh that differs from the file, these readers throw. STL stores each triangle's corners
// separately: OpenMesh merges corners at the same position into one vertex.
//
// Precision: OpenMesh 9's PLY and STL readers pass coordinates as single-precision floats, so
// PLY coordinates written as doubles come back rounded to float (about 7 significant digits).

#include <string>

#include "geometry/io/mesh_file.h"

namespace sa {

/// Reads a PLY file (ASCII or binary) into `mesh`: vertices #V x 3 in file order, simplices
/// #F x 3. Throws InputError `FILE: ...` when OpenMesh cannot read the file (with its message),
/// when a face is not a triangle (naming it and its vertex count), or when OpenMesh dropped or
/// detached faces (saying how many of how many, and why).
MeshFile read_ply(const std::string& path);

/// Reads an STL file (ASCII or binary) into `mesh` (vertices #V x 3, merged; simplices #F x 3).
/// Throws InputError as read_ply().
MeshFile read_stl(const std::string& path);

}  // namespace sa
