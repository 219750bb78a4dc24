#pragma once
// libigl's ASCII .dmat matrices: a first line `cols rows`, then the rows * cols values column by
// column (the first `rows` values are column 0), in any layout.

#include <Eigen/Core>
#include <string>

namespace sa {

/// Reads an ASCII .dmat: rows x cols. Throws InputError `FILE:LINE: ...` on a bad header or
/// number, too few or too many values, and for a binary .dmat (first line `0 0` followed by
/// data): only ASCII is supported. A file holding only `0 0` is an empty matrix.
Eigen::MatrixXd read_dmat(const std::string& path);

/// Writes `cols rows`, then the values column by column, one per line (17 significant digits).
/// Throws InvalidArgumentError on a non-finite value, and InputError when the file cannot be
/// written (nothing is left at `path` then).
void write_dmat(const std::string& path, const Eigen::MatrixXd& matrix);

}  // namespace sa
