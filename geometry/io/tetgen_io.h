#pragma once
// TetGen .node/.ele pairs: tetrahedral meshes.
//
// `.node`: a header `#V dim #attributes #markers` (dim 3, #markers 0 or 1), then #V rows
// `index x y z [attributes...] [marker]`. `.ele`: a header `#T k #attributes` (k = 4; 10-node
// tetrahedra are not supported), then #T rows `index a b c d [attributes...]`. Each file's first
// row index (0 or 1) gives its numbering and its rows must be consecutive; the vertex references
// in the .ele use the .node's numbering. `#` starts a comment.

#include <Eigen/Core>
#include <string>

#include "geometry/io/mesh_file.h"

namespace sa {

/// Reads a .node/.ele pair; `path` is either file, the other is beside it (same name, other
/// extension). Fills `mesh` (vertices #V x 3, simplices #T x 4, 0-based). Throws InputError
/// `FILE:LINE: ...` on a bad header or number, a row with the wrong number of values (e.g.
/// `rest.node:5: expected 4 numbers (index x y z), found 3`), a first index other than 0 or 1, a
/// row index out of sequence, a vertex out of range (`a.ele:9: vertex 40 out of range [1, 38]`,
/// in the .node's numbering) or a count that does not match the rows; InvalidArgumentError when
/// `path` ends neither in .node nor in .ele.
MeshFile read_tetgen(const std::string& path);

/// Writes the .node and the .ele for `path` (its extension must be .node or .ele), 0-based:
/// `#V 3 0 0` and rows `i x y z` (17 significant digits), `#T 4 0` and rows `i a b c d`.
/// `positions` #V x 3, `tets` #T x 4. Throws InvalidArgumentError on arrays of the wrong shape or
/// an index out of range, and InputError when a file cannot be written (each file is replaced only
/// by a complete one; both are written before either is moved into place).
void write_tetgen(const std::string& path, const Eigen::MatrixXd& positions,
                  const Eigen::MatrixXi& tets);

}  // namespace sa
