#pragma once
// Per-face frame fields and direction fields from files, as in libigl's tutorial data
// (inspired_mesh.dmat, snail1-4.dmat, bumpy-cube.dmat, lilium.crossfield, *_b.dmat/*_bc.dmat).
//
// A file gives k 3D vectors (1 <= k <= 4) for some or all faces of a mesh of #F faces, each
// vector as three columns x y z. The layout is recognized from the shape (rows x columns):
//
//   .dmat (ASCII or binary, dmat_io.h) with #F rows, row f for face f:
//     3 columns           one vector per face (e.g. a cross field's direction)     k = 1
//     6 columns           u, then v                                                k = 2
//     1 + 3k columns      a flag (1: the face was a user constraint, else 0), then k vectors:
//                         4, 7, 10 or 13 columns (inspired_mesh.dmat: 7; snail1-4.dmat)
//   .dmat with at most #F rows and 7 columns: a face-index list (bumpy-cube.dmat): per row a
//     0-based face index, then u, then v. With exactly #F rows, a 7-column file is read as
//     flag, u, v unless its column 0 holds each of 0 .. #F-1 once (and #F > 2).
//   .crossfield (lilium.crossfield; libigl's MIQ tutorial writes it with writePolyVf): a first
//     line `k #F` (the number of vectors per face, the number of faces), then one line per face:
//     the flag, then the k vectors.
//   .rawfield (Directional): `N #F`, then N vectors per face; N = 4 only (rawfield_io.h).
//   Any other extension is read as a .dmat. A _b.dmat / _bc.dmat pair: see
//   read_frame_field_constraints().
//
// A face is given when its vectors are not all zero; in a given face every vector must be
// nonzero. A flagged face must be given, and the faces of a face-index list are given and
// constrained. Vectors are returned as in the file: neither projected onto their face nor
// normalized (the caller does that).
//
// u is the first vector. v is the second one when k = 2, or when k = 4 and, in every given face,
// vectors 2 and 3 are -u and -v (a frame written as a symmetric 4-PolyVector). Otherwise v is
// empty and u is one direction per face: k = 1; k = 3 (snail3.dmat holds u and u turned by 60 and
// 120 degrees about the face normal: a 6-direction PolyVector); k = 4 without that symmetry
// (snail4.dmat holds u and u turned by 135, -90 and 45 degrees). All k vectors stay in `vectors`.
//
// Errors are InputError with a one-line message naming the file and the row (0-based, `FILE: row
// 17: ...`) or line (`FILE:LINE: ...`): a shape that matches no layout (naming the shape found
// and the shapes expected for #F faces), a flag other than 0 and 1, a flagged face with zero
// vectors, a zero vector in a given face, a face index that is not an integer, out of range or
// repeated, a value that is not finite, and a file with no given face.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "optim/types.h"

namespace sa {

/// A per-face frame field as read from a file, for a mesh of #F faces.
struct FrameFieldFile {
    /// #F x 3: the first vector per face; zero rows for faces the file leaves free.
    Eigen::MatrixXd u;
    /// #F x 3: the second vector per face (zero rows for free faces), or 0 x 3 when the file
    /// gives one direction per face (see the file comment for when).
    Eigen::MatrixXd v;
    /// #F x 3k: the k vectors per face in the file's order (columns 3j..3j+2: vector j); zero rows
    /// for free faces. k = vectors.cols() / 3; u is columns 0..2.
    Eigen::MatrixXd vectors;
    /// #F: 1 where the file gives this face's vectors, else 0.
    std::vector<unsigned char> given;
    /// #F: 1 where the file marks the face as a user constraint: the flag column, every listed
    /// face of a face-index list, all 0 for a layout without flags.
    std::vector<unsigned char> constrained;
    /// One line saying which layout was recognized, e.g. "flag + 2 vectors per face", for
    /// messages.
    std::string layout;
};

/// Reads a frame field for a mesh of `num_faces` faces from a .dmat (ASCII or binary) or a
/// .crossfield, recognizing the layout from its shape (see the file comment). Throws InputError
/// on a bad file and InvalidArgumentError when num_faces < 0.
FrameFieldFile read_frame_field(const std::string& path, Index num_faces);

/// Reads libigl's pair of constraint files: `b_path` a .dmat with one column of 0-based face
/// indices (#b x 1), `bc_path` a .dmat with #b rows of 3 (one vector) or 6 (u, v) columns, row i
/// for face b(i). The listed faces are given and constrained; the others free. Same rules and
/// errors as read_frame_field (index errors name b_path, vector errors bc_path).
FrameFieldFile read_frame_field_constraints(const std::string& b_path, const std::string& bc_path,
                                            Index num_faces);

}  // namespace sa
