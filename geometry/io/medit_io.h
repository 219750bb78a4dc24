#pragma once
// Medit / Gamma ASCII meshes (.mesh): triangle or tetrahedral meshes.
//
// Read: keywords and counts anywhere in the whitespace (`Dimension` and its value may be on two
// lines), `MeshVersionFormatted n`, `Dimension 2|3`, `Vertices n` then n rows `x y [z] ref`,
// `Triangles n` then n rows `a b c ref`, `Tetrahedra n` then n rows `a b c d ref` (1-based), and
// an optional `End`. Each row is on its own line. These sections are skipped by their row sizes:
// Edges (3), Corners (1), RequiredVertices (1), Ridges (1), RequiredEdges, RequiredTriangles,
// RequiredQuadrilaterals, RequiredTetrahedra, RequiredHexahedra (1 each), Quadrilaterals (5),
// Hexahedra (9), Prisms (7), Pyramids (6), Normals (3), Tangents (3), NormalAtVertices (2),
// TangentAtVertices (2); skipped quadrilaterals, hexahedra, prisms and pyramids are counted in a
// warning.
// Keywords are case-insensitive; `#` starts a comment.

#include <Eigen/Core>
#include <string>

#include "geometry/io/mesh_file.h"

namespace sa {

/// Reads a .mesh file into `mesh`: vertices #V x Dimension, simplices the tetrahedra (#T x 4)
/// when the file has any (its triangles are then ignored), else the triangles (#F x 3), 0-based.
/// Skipped quadrilaterals or hexahedra are reported in `warnings`. Throws InputError
/// `FILE:LINE: ...` on an unknown keyword (naming it), a bad number, a row with the wrong number
/// of values, a vertex index out of range, a count that does not match the rows, a missing
/// `Dimension`, or tetrahedra in a 2D file.
MeshFile read_medit(const std::string& path);

/// Writes `MeshVersionFormatted 2`, `Dimension d` (d = positions.cols(), 2 or 3), `Vertices` with
/// rows `x y [z] 0` (17 significant digits), `Triangles` (#S x 3), `Tetrahedra` (#S x 4) or
/// `Hexahedra` (#S x 8, geometry/mesh/hex_mesh.h's corner order; these two 3D only) with 1-based
/// rows `a b c ... 0`, and `End`. Throws InvalidArgumentError on arrays of the
/// wrong shape or an index out of range, and InputError when the file cannot be written (nothing
/// is left at `path` then).
void write_medit(const std::string& path, const Eigen::MatrixXd& positions,
                 const Eigen::MatrixXi& simplices);

}  // namespace sa
