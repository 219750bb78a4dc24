#pragma once
// Object File Format (.off): triangle meshes.
//
// Read: a header `OFF` (`COFF`, `NOFF` and `CNOFF` are accepted and their extra per-vertex values
// ignored), the counts `#V #F #E` (on the header line or the next), #V rows `x y z` and #F rows
// `3 a b c [colour...]` (0-based). `#` starts a comment. Binary OFF is not supported.

#include <Eigen/Core>
#include <string>

#include "geometry/io/mesh_file.h"

namespace sa {

/// Reads an OFF file into `mesh` (vertices #V x 3, simplices #F x 3). Throws InputError
/// `FILE:LINE: ...` on a bad header or number, a row with too few values, a face that is not a
/// triangle (naming its vertex count), a vertex index out of range, or a count that does not match
/// the rows in the file.
MeshFile read_off(const std::string& path);

/// Writes `OFF`, `#V #F 0`, #V rows `x y z` (#V x 2 positions get z = 0; 17 significant digits)
/// and #F rows `3 a b c` (0-based). `triangles` #F x 3. Throws InvalidArgumentError on arrays of
/// the wrong shape or an index out of range, and InputError when the file cannot be written
/// (nothing is left at `path` then).
void write_off(const std::string& path, const Eigen::MatrixXd& positions,
               const Eigen::MatrixXi& triangles);

}  // namespace sa
