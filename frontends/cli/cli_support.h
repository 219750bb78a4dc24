#pragma once
// Helpers shared by the `sa` subcommands: reading positions from any supported file, refusing to
// overwrite outputs unless asked, and the progress logger.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "optim/logger.h"
#include "optim/types.h"

namespace sa::cli {

/// Positions from `path`: the vertices of a mesh file (by extension), the `resV` record of a
/// result file, or the initial block of a plain-text problem. Checks #V rows and keeps the first
/// `dimension` columns (dropped columns must be zero: a planar map saved with z = 0).
Eigen::MatrixXd read_positions(const std::string& path, Index expected_rows, int dimension);

/// Throws InvalidArgumentError when `path`'s format cannot hold simplices of `dimension` (.obj and
/// .off hold triangles, .node/.ele tetrahedra; .ply and .stl are not written), so that a run never
/// ends in a write that was bound to fail.
void check_output_format(const std::string& path, int dimension);

/// Throws InputError when `path` exists and `overwrite` is false.
void check_writable(const std::string& path, bool overwrite);

/// The extension of `path` in lower case, with its dot ("" when none).
std::string extension(const std::string& path);

/// The process's peak resident memory so far, in GB.
double peak_memory_gb();

/// A logger that writes each line to stderr (nothing when `quiet`).
Logger stderr_logger(bool quiet);

}  // namespace sa::cli
