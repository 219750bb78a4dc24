#pragma once
// Wavefront OBJ: triangle meshes with optional texture coordinates.
//
// Read: `v x y [z [w]]` (extra values such as vertex colours are ignored; a file whose `v` lines
// all have 2 numbers is 2D, #V x 2, otherwise #V x 3 with z = 0 for 2-number lines), `vt u v [w]`
// and `f` lines with corners `a`, `a/b`, `a//c` or `a/b/c` (1-based, or negative: relative to the
// vertices defined so far). Only triangles: a face with another vertex count is an error. `vn`,
// `g`, `o`, `s`, `l`, `usemtl`, `mtllib` and unknown keywords are ignored; `#` starts a comment.
// Texture coordinates: all faces have them or none (mixing is an error).

#include <Eigen/Core>
#include <string>

#include "geometry/io/mesh_file.h"

namespace sa {

/// Reads an OBJ file. Fills `mesh` (vertices #V x 2 or #V x 3, simplices #F x 3),
/// `texture_coordinates` (#VT x 2) and `face_texture_indices` (#F x 3, 0-based rows into it) when
/// the faces have texture coordinates, and `initial` (#V x 2, the uv of each vertex) when every
/// vertex is in a face and gets one uv value through all of its corners (values are compared, not
/// indices); otherwise `initial` stays empty and a warning names the vertex and the two lines.
/// Throws InputError `FILE:LINE: ...` on a bad number, an index out of range or 0, a face that is
/// not a triangle, or faces that mix corners with and without texture coordinates.
MeshFile read_obj(const std::string& path);

/// Writes `v x y z` lines (#V x 2 positions get z = 0; 17 significant digits), then `vt u v`
/// lines and `f a/t b/t c/t` faces when `texture_coordinates` (#VT x 2) is given, else `f a b c`.
/// `face_texture_indices` (#F x 3, 0-based rows into texture_coordinates) gives each corner's
/// texture coordinate; when null, the corner of vertex i uses row i (then #VT must equal #V).
/// Throws InvalidArgumentError on arrays of the wrong shape or an index out of range, and
/// InputError when the file cannot be written (nothing is left at `path` then).
void write_obj(const std::string& path, const Eigen::MatrixXd& positions,
               const Eigen::MatrixXi& triangles,
               const Eigen::MatrixXd* texture_coordinates = nullptr,
               const Eigen::MatrixXi* face_texture_indices = nullptr);

}  // namespace sa
