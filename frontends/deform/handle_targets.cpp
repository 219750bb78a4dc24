#include "frontends/deform/handle_targets.h"

#include <set>
#include <unordered_map>

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

HandleTargets read_handle_targets(const std::string& handles_path, const std::string& targets_path,
                                  Index num_vertices, int dimension) {
    if (dimension != 2 && dimension != 3) {
        throw InvalidArgumentError("read_handle_targets: dimension " + std::to_string(dimension) +
                                   " (expected 2 or 3)");
    }
    if (targets_path.empty()) throw InvalidArgumentError("read_handle_targets: no targets file");
    HandleTargets result;

    // Targets alone: rows `index x y z`.
    if (handles_path.empty()) {
        if (is_mesh_file(targets_path)) {
            throw InputError(targets_path +
                             ": a mesh file gives positions, not handles; give the handle list "
                             "too, or rows `index x y z`");
        }
        PositionRows rows = read_position_rows(targets_path, dimension, num_vertices);
        if (!rows.indexed()) {
            throw InputError(targets_path + ":" + std::to_string(rows.lines.front()) +
                             ": rows without a vertex index; alone, the targets file needs rows "
                             "`index x" +
                             (dimension == 3 ? " y z`" : " y`") + " (or give the handle list)");
        }
        result.handles = std::move(rows.indices);
        result.targets = std::move(rows.positions);
        return result;
    }

    // The handle list, each handle in range.
    std::vector<int> handle_lines;
    result.handles = read_index_list(handles_path, &handle_lines);
    if (result.handles.empty()) throw InputError(handles_path + ": no handle vertex");
    for (std::size_t k = 0; k < result.handles.size(); ++k) {
        if (result.handles[k] >= num_vertices) {
            throw InputError(handles_path + ":" + std::to_string(handle_lines[k]) +
                             ": handle vertex " + std::to_string(result.handles[k]) +
                             " outside [0, " + std::to_string(num_vertices) + ") (the mesh has " +
                             vertices_text(num_vertices) + ")");
        }
    }
    const Index num_handles = static_cast<Index>(result.handles.size());

    if (is_mesh_file(targets_path)) {
        const Eigen::MatrixXd positions = mesh_positions(targets_path, dimension);
        if (positions.rows() != num_vertices) {
            throw InputError(targets_path + ": " + vertices_text(positions.rows()) +
                             ", the rest mesh has " + std::to_string(num_vertices));
        }
        result.targets = rows_at(positions, result.handles);
        return result;
    }

    PositionRows rows = read_position_rows(targets_path, dimension, num_vertices);
    if (rows.indexed()) {
        // Exactly the handles, in any order.
        std::unordered_map<Index, std::size_t> slot;
        for (std::size_t k = 0; k < result.handles.size(); ++k) slot[result.handles[k]] = k;
        result.targets.resize(num_handles, dimension);
        std::vector<unsigned char> given(result.handles.size(), 0);
        for (std::size_t r = 0; r < rows.indices.size(); ++r) {
            const auto it = slot.find(rows.indices[r]);
            if (it == slot.end()) {
                throw InputError(targets_path + ":" + std::to_string(rows.lines[r]) + ": vertex " +
                                 std::to_string(rows.indices[r]) + " is not a handle of " +
                                 handles_path);
            }
            result.targets.row(it->second) = rows.positions.row(r);
            given[it->second] = 1;
        }
        for (std::size_t k = 0; k < given.size(); ++k) {
            if (!given[k]) {
                throw InputError(targets_path + ": no target for handle vertex " +
                                 std::to_string(result.handles[k]) + " (" + handles_path + ":" +
                                 std::to_string(handle_lines[k]) + ")");
            }
        }
        return result;
    }
    const Index n = static_cast<Index>(rows.positions.rows());
    if (n == num_vertices) {
        result.targets = rows_at(rows.positions, result.handles);
    } else if (n == num_handles) {
        result.targets = std::move(rows.positions);
    } else {
        throw InputError(targets_path + ": " + std::to_string(n) +
                         " rows; expected one per vertex (" + std::to_string(num_vertices) +
                         ") or one per handle of " + handles_path + " (" +
                         std::to_string(num_handles) + ")");
    }
    return result;
}

Eigen::MatrixXd move_handles(const Eigen::MatrixXd& rest, const HandleTargets& handle_targets) {
    const auto& [handles, targets] = handle_targets;
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
