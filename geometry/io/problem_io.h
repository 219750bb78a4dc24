#pragma once
// The plain-text problem format and result records of the TLC benchmark (../shared/data/tlc).
//
// Problem (`input`): `#V dim` then #V rows of rest positions; `#V dim2` then #V rows of initial
// positions (dim2 may differ from dim: a 3D surface mapped to the plane); `#S k` then #S rows of
// k 0-based vertex indices (k = 3 triangles, 4 tetrahedra); then optionally `#H` and #H 0-based
// handle indices (any layout). `#` starts a comment.
//
// Result records (`result`): records `name dim1 [dim2 ...]`, each followed by one line of
// dim1 * dim2 * ... values; `resV n d` holds n x d positions, row-major.

#include <Eigen/Core>
#include <string>

#include "geometry/io/mesh_file.h"

namespace sa {

/// Reads a problem file: fills `mesh` (vertices #V x dim, simplices #S x k), `initial`
/// (#V x dim2) and `handles` (empty when the file has none). Throws InputError `FILE:LINE: ...`
/// on a bad header or number, a row with the wrong number of values, an index out of range, a
/// repeated handle, initial positions whose count differs from the rest ones, missing rows, or
/// data after the handles.
MeshFile read_problem(const std::string& path);

/// Reads the `resV n d` record of a result file: n x d. Throws InputError when the file has no
/// such record, or on a malformed record header or value line before it or in it.
Eigen::MatrixXd read_result_positions(const std::string& path);

/// Writes one record, `resV n d` and a line of the n x d `positions` row-major (17 significant
/// digits). Throws InvalidArgumentError on a non-finite value and InputError when the file cannot
/// be written (nothing is left at `path` then).
void write_result_records(const std::string& path, const Eigen::MatrixXd& positions);

}  // namespace sa
