#pragma once
// Reading and writing meshes in any supported file format, chosen by the file's extension.
//
// Every reader throws InputError on a file it cannot use, with a one-line message
// `FILE:LINE: what is wrong` (or `FILE: what is wrong` when no line is known), e.g.
//   mesh.obj:17: face with 4 vertices; only triangles are supported
//   mesh.off: cannot open (No such file or directory)
// Readers check the file itself (numbers, counts, index ranges, element types) but not the mesh's
// geometry: call validate_mesh() on the result. Writers throw InvalidArgumentError on arrays of
// the wrong shape (naming the function and the row) and InputError when the file cannot be
// written; they write through AtomicFile, so that on any error nothing is left at the
// destination and an existing file there is untouched.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "geometry/mesh/simplicial_mesh.h"
#include "optim/types.h"

namespace sa {

/// What a mesh file holds.
struct MeshFile {
    /// Rest vertices (#V x 2 or #V x 3) and simplices (#S x 3 or #S x 4, 0-based).
    SimplicialMesh mesh;
    /// Initial map, #V x d, when the file has one (the problem format's second block, an OBJ's
    /// per-vertex texture coordinates).
    std::optional<Eigen::MatrixXd> initial;
    /// Handle vertices (0-based), when the file lists them.
    std::vector<Index> handles;
    /// OBJ `vt` rows, #VT x 2; empty if none.
    Eigen::MatrixXd texture_coordinates;
    /// #F x 3 0-based rows into texture_coordinates, one per face; empty if none.
    Eigen::MatrixXi face_texture_indices;
    /// One-line notes about things that did not stop the read.
    std::vector<std::string> warnings;
};

/// Throws InputError `FILE: cannot open (reason)` unless `path` is a file that can be opened for
/// reading (`FILE: cannot open (Is a directory)` for a folder). Every reader checks this first.
void check_input_file(const std::string& path);

/// Reads a mesh by its extension (case-insensitive): .obj (obj_io.h), .off (off_io.h), .ply
/// (ply_io.h), .stl (openmesh_io.h), .vtk and .vtu (vtk_io.h), .mesh (medit_io.h), .node and .ele
/// (tetgen_io.h); any other file is read as the plain-text problem format (problem_io.h).
MeshFile read_mesh_file(const std::string& path);

/// Writes a mesh by its extension (case-insensitive): .vtu, .vtk, .obj, .off, .mesh, .node or
/// .ele (writes both the .node and the .ele). `positions` #V x 2 or #V x 3 (2D positions get
/// z = 0 where a format needs 3), `simplices` #S x 3 or #S x 4 (0-based; .obj and .off hold
/// triangles only, .node/.ele tetrahedra only). Any other extension writes result records
/// (problem_io.h: `resV #V d` and the positions; `simplices` is not written), except .ply and .stl,
/// which are readable only and throw InvalidArgumentError.
void write_mesh_file(const std::string& path, const Eigen::MatrixXd& positions,
                     const Eigen::MatrixXi& simplices);

}  // namespace sa
