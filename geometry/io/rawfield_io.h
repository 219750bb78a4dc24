#pragma once
// Directional's `.rawfield` files (Vaxman et al.'s Directional library writes a face-based field
// so): a first line `N #F`, then one line per face with N vectors of 3 extrinsic coordinates
// (tangent to the face). For N = 4, a cross or frame field is written as a symmetric
// 4-PolyVector u, v, -u, -v.
//
// Only N = 4 is a frame field: u is the first vector and v the second; the third and fourth must
// be -u and -v (within 1e-6 of the larger length). Any other N, a face count other than the
// mesh's, a line without 3N finite numbers, a broken symmetry, a zero vector beside nonzero ones,
// extra data or no nonzero face is an InputError `FILE:LINE: what` (or `FILE: what`). A face whose
// vectors are all zero is left free. Vectors are returned as in the file (the caller projects and
// normalizes).

#include <string>

#include "geometry/io/frame_field_io.h"

namespace sa {

/// Reads a .rawfield for a mesh of `num_faces` faces (FrameFieldFile as in frame_field_io.h, with
/// `constrained` all 0 and `vectors` the four vectors per face). read_frame_field() calls it for
/// the .rawfield extension. Throws InvalidArgumentError when num_faces < 0.
FrameFieldFile read_rawfield(const std::string& path, Index num_faces);

}  // namespace sa
