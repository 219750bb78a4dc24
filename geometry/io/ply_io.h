#pragma once
// PLY triangle meshes (Stanford polygon format; ASCII, binary little- and big-endian), read here
// without a library: OpenMesh's PLY reader hung, crashed or allocated without bound on malformed
// headers and bodies (tests/fuzz/regressions/ply_stl), and passed coordinates as floats.
//
// The header names the elements in the order of the body and their properties: the `vertex`
// element's scalar properties x, y, z give the positions (any numeric type, read as double),
// the `face` element's list property `vertex_indices` (or `vertex_index`) the triangles. Other
// properties and elements are read and dropped. Faces are kept as the file lists them, as the OBJ
// reader does (no merging, no manifold repair: the front-ends check the topology they need).

#include <string>

#include "geometry/io/mesh_file.h"

namespace sa {

/// Reads a PLY file into `mesh`: vertices #V x 3 in file order, simplices #F x 3. Throws
/// InputError `FILE:LINE: ...` (`FILE: byte N: ...` in a binary body) naming what is malformed:
/// a header line, a missing vertex element or coordinate, a count the file cannot hold, a body
/// cut short or holding a non-number, a face that is not a triangle (naming it and its vertex
/// count), a vertex index out of range or repeated in a face.
MeshFile read_ply(const std::string& path);

}  // namespace sa
