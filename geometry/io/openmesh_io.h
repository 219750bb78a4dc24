#pragma once
// STL triangle meshes, read through OpenMesh (ASCII and binary). OpenMesh lives in the plugin
// libsa_openmesh.so, loaded on first use (geometry/io/openmesh_plugin.h): read_stl throws Error
// naming the folders tried when it cannot be found. (PLY files are read without OpenMesh:
// ply_io.h.)
//
// OpenMesh builds a halfedge mesh: it detaches faces that would make the mesh non-manifold
// (a "complex edge" or "complex vertex": it re-adds them on copies of their vertices) and drops
// faces with repeated or out-of-range vertices, mostly without a message. Rather than return a
// mesh that differs from the file, read_stl throws. STL stores each triangle's corners
// separately: OpenMesh merges corners at the same position into one vertex. STL coordinates are
// single-precision floats.

#include <string>

#include "geometry/io/mesh_file.h"

namespace sa {

/// Reads an STL file (ASCII or binary) into `mesh`: vertices #V x 3 (merged), simplices #F x 3.
/// Throws InputError `FILE: ...` when OpenMesh cannot read the file (with its message), when a
/// face is not a triangle (naming it and its vertex count), or when OpenMesh dropped or detached
/// faces (saying how many of how many, and why).
MeshFile read_stl(const std::string& path);

}  // namespace sa
