#include "frontends/deform/handle_targets.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <exception>
#include <optional>
#include <set>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "geometry/io/index_list_io.h"
#include "geometry/io/indexed_positions_io.h"
#include "geometry/io/mesh_file.h"
#include "geometry/io/text_reader.h"
#include "optim/errors.h"

namespace sa {

namespace {

bool is_mesh_file(const std::string& path) {
    static const std::set<std::string> extensions = {".node", ".ele", ".mesh", ".obj", ".off",
                                                     ".vtk",  ".vtu", ".ply",  ".stl"};
    return extensions.count(io::lower_extension(path)) > 0;
}

/// The first `dimension` columns of a mesh file's vertices; the others must be zero.
Eigen::MatrixXd mesh_positions(const std::string& path, int dimension) {
    const Eigen::MatrixXd vertices = read_mesh_file(path).mesh.vertices;
    if (vertices.cols() < dimension) {
        throw InputError(path + ": vertices have " + std::to_string(vertices.cols()) +
                         " coordinates, the map needs " + std::to_string(dimension));
    }
    for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
        for (Eigen::Index c = dimension; c < vertices.cols(); ++c) {
            if (vertices(v, c) != 0.0) {
                throw InputError(path + ": vertex " + std::to_string(v) + " has coordinate " +
                                 std::to_string(c) + " = " + std::to_string(vertices(v, c)) +
                                 "; a map of triangles is planar (" + std::to_string(dimension) +
                                 " coordinates)");
            }
        }
    }
    return vertices.leftCols(dimension);
}

/// Rows of `per_vertex` at the handles.
Eigen::MatrixXd rows_at(const Eigen::MatrixXd& per_vertex, const std::vector<Index>& handles) {
    Eigen::MatrixXd targets(handles.size(), per_vertex.cols());
    for (std::size_t k = 0; k < handles.size(); ++k) targets.row(k) = per_vertex.row(handles[k]);
    return targets;
}

std::string vertices_text(Index n) {
    return std::to_string(n) + " vertices";
}

}  // namespace

namespace {

/// `path:line` of each row.
std::vector<std::string> row_origins(const std::string& path, const std::vector<int>& lines) {
    std::vector<std::string> origins;
    origins.reserve(lines.size());
    for (const int line : lines) origins.push_back(path + ":" + std::to_string(line));
    return origins;
}

/// Whether the first number of every row of `path` (a count line aside) is an integer.
bool integer_first_column(const std::string& path) {
    io::TextReader reader(path);
    bool first_line = true;
    while (reader.next_line()) {
        const auto& tokens = reader.tokens();
        if (std::exchange(first_line, false) && tokens.size() == 1) continue;  // a count
        long long value = 0;
        const std::string_view token = tokens.front();
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc() || end != token.data() + token.size()) return false;
    }
    return true;
}

struct Targets {
    Eigen::MatrixXd positions;         ///< #handles x d
    std::vector<std::string> origins;  ///< #handles
};

/// Targets from rows `index x y (z)`: exactly the handles, in any order.
Targets indexed_targets(const PositionRows& rows, const IndexList& handles,
                        const std::string& targets_path, const std::string& handles_path) {
    std::unordered_map<Index, std::size_t> slot;
    for (std::size_t k = 0; k < handles.indices.size(); ++k) slot[handles.indices[k]] = k;
    Eigen::MatrixXd targets(handles.indices.size(), rows.positions.cols());
    std::vector<std::string> origins(handles.indices.size());
    std::vector<unsigned char> given(handles.indices.size(), 0);
    for (std::size_t r = 0; r < rows.indices.size(); ++r) {
        const auto it = slot.find(rows.indices[r]);
        if (it == slot.end()) {
            throw InputError(targets_path + ":" + std::to_string(rows.lines[r]) + ": vertex " +
                             std::to_string(rows.indices[r]) + " is not a handle of " +
                             handles_path);
        }
        targets.row(it->second) = rows.positions.row(r);
        origins[it->second] = targets_path + ":" + std::to_string(rows.lines[r]);
        given[it->second] = 1;
    }
    for (std::size_t k = 0; k < given.size(); ++k) {
        if (!given[k]) {
            throw InputError(targets_path + ": no target for handle vertex " +
                             std::to_string(handles.indices[k]) + " (" + handles_path + ":" +
                             std::to_string(handles.lines[k]) + ")");
        }
    }
    return {std::move(targets), std::move(origins)};
}

/// Targets from rows `x y (z)`: one per vertex or one per handle, in the handle list's order.
/// `per` receives "vertex" or "handle".
Targets plain_targets(const PositionRows& rows, const IndexList& handles, Index num_vertices,
                      const std::string& targets_path, const std::string& handles_path,
                      std::string& per) {
    const Index n = static_cast<Index>(rows.positions.rows());
    const Index num_handles = static_cast<Index>(handles.indices.size());
    // Every vertex a handle, listed out of order: a row per vertex and a row per handle differ.
    if (n == num_vertices && n == num_handles &&
        !std::is_sorted(handles.indices.begin(), handles.indices.end())) {
        throw InputError(targets_path + ": " + std::to_string(n) +
                         " rows, one per vertex and one per handle of " + handles_path +
                         ", whose order differs; give rows `index x y" +
                         (rows.positions.cols() == 3 ? " z`" : "`") + " instead");
    }
    const std::vector<std::string> origins = row_origins(targets_path, rows.lines);
    if (n == num_vertices) {
        per = "vertex";
        std::vector<std::string> at_handles;
        for (const Index h : handles.indices) at_handles.push_back(origins[h]);
        return {rows_at(rows.positions, handles.indices), std::move(at_handles)};
    }
    if (n == num_handles) {
        per = "handle";
        return {rows.positions, origins};
    }
    throw InputError(targets_path + ": " + std::to_string(n) + " rows; expected one per vertex (" +
                     std::to_string(num_vertices) + ") or one per handle of " + handles_path +
                     " (" + std::to_string(num_handles) + ")");
}

}  // namespace

HandleTargets read_handle_targets(const std::string& handles_path, const std::string& targets_path,
                                  Index num_vertices, int dimension) {
    if (dimension != 2 && dimension != 3) {
        throw InvalidArgumentError("read_handle_targets: dimension " + std::to_string(dimension) +
                                   " (expected 2 or 3)");
    }
    if (targets_path.empty()) throw InvalidArgumentError("read_handle_targets: no targets file");
    HandleTargets result;
    const std::string xy = dimension == 3 ? "x y z" : "x y";

    // Targets alone: rows `index x y z`.
    if (handles_path.empty()) {
        if (is_mesh_file(targets_path)) {
            throw InputError(targets_path + ": a mesh file gives positions, not handles; give " +
                             "the handle list too, or rows `index " + xy + "`");
        }
        PositionRows rows = read_position_rows(targets_path, dimension, num_vertices);
        if (!rows.indexed()) {
            throw InputError(targets_path + ":" + std::to_string(rows.lines.front()) +
                             ": rows without a vertex index; alone, the targets file needs " +
                             "rows `index " + xy + "` (or give the handle list)");
        }
        result.handles = std::move(rows.indices);
        result.targets = std::move(rows.positions);
        result.origins = row_origins(targets_path, rows.lines);
        result.reading = "rows `index " + xy + "` of " + targets_path;
        return result;
    }

    // The handle list, each handle in range.
    const IndexList handles = read_index_list(handles_path);
    if (handles.indices.empty()) throw InputError(handles_path + ": no handle vertex");
    for (std::size_t k = 0; k < handles.indices.size(); ++k) {
        if (handles.indices[k] >= num_vertices) {
            throw InputError(handles_path + ":" + std::to_string(handles.lines[k]) +
                             ": handle vertex " + std::to_string(handles.indices[k]) +
                             " outside [0, " + std::to_string(num_vertices) + ") (the mesh has " +
                             vertices_text(num_vertices) + ")");
        }
    }
    result.handles = handles.indices;
    const std::string first_number = first_number_reading(handles_path, handles);
    const std::string handles_note = first_number.empty() ? "" : "; " + first_number;

    if (is_mesh_file(targets_path)) {
        const Eigen::MatrixXd positions = mesh_positions(targets_path, dimension);
        if (positions.rows() != num_vertices) {
            throw InputError(targets_path + ": " + vertices_text(positions.rows()) +
                             ", the rest mesh has " + std::to_string(num_vertices));
        }
        result.targets = rows_at(positions, result.handles);
        for (const Index h : result.handles)
            result.origins.push_back(targets_path + " (vertex " + std::to_string(h) + ")");
        result.reading = handles_path + " at their vertices of " + targets_path + handles_note;
        return result;
    }

    // Rows of positions. In 2D, three numbers a row are `index x y` or `x y 0`: each reading is
    // tried against the handles, and a file that both fit is refused.
    std::optional<PositionRows> by_count;
    std::exception_ptr by_count_error;
    try {
        by_count = read_position_rows(targets_path, dimension, num_vertices);
    } catch (const InputError&) {
        if (dimension == 3) throw;
        by_count_error = std::current_exception();
    }
    if (by_count && !by_count->indexed()) {
        std::string per;
        Targets plain =
            plain_targets(*by_count, handles, num_vertices, targets_path, handles_path, per);
        result.targets = std::move(plain.positions);
        result.origins = std::move(plain.origins);
        result.reading = "rows `" + xy + "` of " + targets_path + ", one per " + per + handles_note;
        return result;
    }
    std::optional<Targets> as_indexed, as_plain;
    std::exception_ptr indexed_error = by_count_error, plain_error;
    if (by_count) {
        try {
            as_indexed = indexed_targets(*by_count, handles, targets_path, handles_path);
        } catch (const InputError&) {
            indexed_error = std::current_exception();
        }
    }
    std::string per;
    if (dimension == 2) {
        try {
            const PositionRows plain =
                read_position_rows(targets_path, dimension, num_vertices, RowLayout::plain);
            as_plain = plain_targets(plain, handles, num_vertices, targets_path, handles_path, per);
        } catch (const InputError&) {
            plain_error = std::current_exception();
        }
    }
    if (as_indexed && as_plain) {
        const std::string both = ": rows of three numbers fit both `index x y` (the handles of ";
        throw InputError(targets_path + both + handles_path + ") and `x y 0` (one per " + per +
                         "); write rows `x y`, or rows `index x y` without --handles");
    }
    if (as_indexed) {
        result.targets = std::move(as_indexed->positions);
        result.origins = std::move(as_indexed->origins);
        result.reading = "rows `index " + xy + "` of " + targets_path + handles_note;
        return result;
    }
    if (as_plain) {
        result.targets = std::move(as_plain->positions);
        result.origins = std::move(as_plain->origins);
        result.reading = "rows `x y 0` of " + targets_path + ", one per " + per + handles_note;
        return result;
    }
    // Neither fits: why the `index x y` reading failed, unless the first numbers are not all
    // integers (then the rows were meant as positions).
    std::rethrow_exception(plain_error && !integer_first_column(targets_path) ? plain_error
                                                                              : indexed_error);
}

void check_target_reach(const Eigen::MatrixXd& rest, const HandleTargets& handle_targets) {
    if (rest.rows() == 0 || handle_targets.targets.cols() != rest.cols()) return;
    const Eigen::RowVectorXd low = rest.colwise().minCoeff(), high = rest.colwise().maxCoeff();
    const double diagonal = (high - low).stableNorm();
    for (Eigen::Index k = 0; k < handle_targets.targets.rows(); ++k) {
        const Eigen::RowVectorXd target = handle_targets.targets.row(k);
        const double distance = (target - target.cwiseMax(low).cwiseMin(high)).stableNorm();
        if (distance <= kMaxPoseStretch * diagonal) continue;
        const std::size_t at = static_cast<std::size_t>(k);
        char numbers[200];
        std::snprintf(numbers, sizeof numbers,
                      " lies %.3g from the rest shape, %.3g times its diagonal; a pose may "
                      "stretch the rest shape at most %g times",
                      distance, distance / diagonal, kMaxPoseStretch);
        throw InputError(
            (at < handle_targets.origins.size() ? handle_targets.origins[at] + ": " : "") +
            "the target of handle vertex " + std::to_string(handle_targets.handles[at]) + numbers +
            " (beyond, its distortions overflow double arithmetic)");
    }
}

Eigen::MatrixXd move_handles(const Eigen::MatrixXd& rest, const HandleTargets& handle_targets) {
    const auto& handles = handle_targets.handles;
    const auto& targets = handle_targets.targets;
    if (targets.rows() != static_cast<Eigen::Index>(handles.size()) ||
        (!handles.empty() && targets.cols() != rest.cols())) {
        throw InvalidArgumentError("move_handles: " + std::to_string(handles.size()) +
                                   " handles, targets " + std::to_string(targets.rows()) + " x " +
                                   std::to_string(targets.cols()) + ", rest positions " +
                                   std::to_string(rest.rows()) + " x " +
                                   std::to_string(rest.cols()));
    }
    Eigen::MatrixXd moved = rest;
    for (std::size_t k = 0; k < handles.size(); ++k) {
        if (handles[k] < 0 || handles[k] >= rest.rows()) {
            throw InvalidArgumentError("move_handles: handle vertex " + std::to_string(handles[k]) +
                                       " outside [0, " + std::to_string(rest.rows()) + ")");
        }
        moved.row(handles[k]) = targets.row(k);
    }
    return moved;
}

}  // namespace sa
