#pragma once
// Helpers shared by the `sa` subcommands: exit statuses, reading positions from any supported
// file, checks of the meshes read, messages on one line, and the progress logger.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "energies/distortion.h"
#include "geometry/io/mesh_file.h"
#include "geometry/mesh/simplicial_mesh.h"
#include "optim/errors.h"
#include "optim/logger.h"
#include "optim/types.h"

namespace sa::cli {

/// The command's exit statuses (README.md, "Exit status").
enum ExitStatus : int {
    kExitVerified = 0,       ///< the result was verified and written
    kExitNotVerified = 1,    ///< the result did not pass verification; written, and says so
    kExitBadInput = 2,       ///< bad input, option or output location: one line, nothing written
    kExitInternalError = 3,  ///< a bug: one line, nothing written
    kExitOutOfMemory = 4,    ///< an allocation failed: one line, nothing written
};

/// Positions from `path`: the vertices of a mesh file (by extension), the `resV` record of a
/// result file, or the initial block of a plain-text problem. Checks #V rows and keeps the first
/// `dimension` columns (dropped columns must be zero: a planar map saved with z = 0).
Eigen::MatrixXd read_positions(const std::string& path, Index expected_rows, int dimension);

/// Throws InvalidArgumentError when `path`'s format cannot hold simplices of `dimension` (.obj and
/// .off hold triangles, .node/.ele tetrahedra; .ply and .stl are not written), so that a run never
/// ends in a write that was bound to fail.
void check_output_format(const std::string& path, int dimension);

/// `parse(value)`, whose InvalidArgumentError gets the option and value in front: "--energy frob:
/// unknown distortion 'frob' (...)" (the parsers name the value, not the option it came with).
template <class Parse>
auto parse_option(const std::string& option, const std::string& value, Parse&& parse)
    -> decltype(parse(value)) {
    try {
        return parse(value);
    } catch (const InvalidArgumentError& e) {
        throw InvalidArgumentError(option + " " + value + ": " + e.what());
    }
}

/// The distortion named `value` of `option` when it is one of `allowed`; otherwise throws
/// InvalidArgumentError "OPTION VALUE: expected A, B or C" listing only those.
DistortionType parse_distortion_among(const std::string& option, const std::string& value,
                                      const std::vector<DistortionType>& allowed);

/// Throws InputError `PATH: the mesh has no vertices` (or no simplices), naming the file the mesh
/// was read from, so that later checks (handles, fields) do not blame another file.
void require_simplices(const SimplicialMesh& mesh, const std::string& path);

/// The mesh file `path` given as `option`, read (the activity "reading OPTION PATH"), each of its
/// reader's warnings written on stderr as `sa: warning: ...` (one line each), and checked by
/// require_simplices(). With `triangles_for` not empty, a mesh of tetrahedra is refused:
/// InputError `PATH: TRIANGLES_FOR needs a triangle mesh`.
MeshFile read_input_mesh(const std::string& option, const std::string& path,
                         const std::string& triangles_for = "");

/// `text` on one line, printable: line breaks become "; ", other control characters and bytes
/// that are not UTF-8 become `\xNN`.
std::string one_line(const std::string& text);

/// The extension of `path` in lower case, with its dot ("" when none).
std::string extension(const std::string& path);

/// `path` with its extension replaced by `ext` (".png"), or added when it has none.
std::string with_extension(const std::string& path, const std::string& ext);

/// The process's peak resident memory so far, in GB.
double peak_memory_gb();

/// A logger that writes each line to stderr (nothing when `quiet`).
Logger stderr_logger(bool quiet);

}  // namespace sa::cli
