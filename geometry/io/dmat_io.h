#pragma once
// libigl's .dmat matrices.
//
// ASCII: a first line `cols rows`, then the rows * cols values column by column (the first `rows`
// values are column 0), in any layout.
// Binary (libigl's writeDMAT with ascii = false): a first line `0 0`, a second line `cols rows`,
// then the rows * cols values as little-endian IEEE doubles (8 bytes each), column by column,
// and nothing after them.

#include <Eigen/Core>
#include <string>

namespace sa {

/// Reads an ASCII or binary .dmat: rows x cols. A first line `0 0` followed by anything but
/// whitespace starts a binary .dmat; a file holding only `0 0` is an empty ASCII matrix. Throws
/// InputError `FILE:LINE: ...` or `FILE: ...` on a bad header or number, too few or too many
/// values (in binary: bytes), and a value that is not finite.
Eigen::MatrixXd read_dmat(const std::string& path);

/// Writes `cols rows`, then the values column by column, one per line (17 significant digits).
/// Throws InvalidArgumentError on a non-finite value, and InputError when the file cannot be
/// written (nothing is left at `path` then).
void write_dmat(const std::string& path, const Eigen::MatrixXd& matrix);

}  // namespace sa
