#include "geometry/io/obj_io.h"

#include <array>
#include <sstream>
#include <vector>

#include "geometry/io/atomic_file.h"
#include "geometry/io/text_reader.h"
#include "geometry/io/write_checks.h"
#include "optim/errors.h"

namespace sa {
namespace {

// Resolves a 1-based or negative (relative) OBJ index against the `count` items defined so far;
// returns the 0-based index.
int resolve_index(const io::TextReader& reader, std::string_view token, long long count,
                  const char* what) {
    const long long index = reader.to_integer(token, what);
    if (index == 0) reader.fail(std::string(what) + " index 0; OBJ indices start at 1");
    const long long resolved = index > 0 ? index - 1 : count + index;
    if (resolved < 0 || resolved >= count) {
        std::ostringstream message;
        message << what << " " << index << " out of range ";
        if (count == 0)
            message << "(no " << what << " defined so far)";
        else if (index > 0)
            message << "[1, " << count << "]";
        else
            message << "[-" << count << ", -1]";
        reader.fail(message.str());
    }
    return static_cast<int>(resolved);
}

std::string format_uv(double u, double v) {
    std::ostringstream out;
    out.precision(17);
    out << "(" << u << ", " << v << ")";
    return out.str();
}

}  // namespace

MeshFile read_obj(const std::string& path) {
    io::TextReader reader(path);
    std::vector<double> coordinates;  // 3 per vertex
    std::vector<double> uvs;          // 2 per texture coordinate
    std::vector<int> faces;           // 3 per face
    std::vector<int> face_uvs;        // 3 per face, when the faces have texture coordinates
    std::vector<int> face_lines;      // the line of each face, for warnings
    int vertex_count = 0;
    int uv_count = 0;
    bool any_3d = false;
    int first_2d_line = 0;
    int first_face_line = 0;
    bool faces_have_uv = false;
    MeshFile result;

    while (reader.next_line()) {
        const auto& tokens = reader.tokens();
        const std::string_view keyword = tokens[0];
        const std::size_t values = tokens.size() - 1;
        if (keyword == "v") {
            if (values < 2)
                reader.fail("vertex with " + std::to_string(values) +
                            " coordinates; expected x y [z [w]]");
            std::array<double, 3> p{0.0, 0.0, 0.0};
            for (std::size_t i = 1; i < tokens.size(); ++i) {
                const double value = reader.to_double(tokens[i], "coordinate");
                if (i <= 3) p[i - 1] = value;
            }
            if (values >= 3)
                any_3d = true;
            else if (first_2d_line == 0)
                first_2d_line = reader.line_number();
            coordinates.insert(coordinates.end(), p.begin(), p.end());
            ++vertex_count;
        } else if (keyword == "vt") {
            if (values < 2 || values > 3)
                reader.fail("texture coordinate with " + std::to_string(values) +
                            " values; expected u v [w]");
            uvs.push_back(reader.to_double(tokens[1], "texture coordinate"));
            uvs.push_back(reader.to_double(tokens[2], "texture coordinate"));
            if (values == 3) reader.to_double(tokens[3], "texture coordinate");
            ++uv_count;
        } else if (keyword == "f") {
            if (values != 3)
                reader.fail("face with " + std::to_string(values) +
                            " vertices; only triangles are supported");
            int with_uv = 0;
            std::array<int, 3> corner_uv{-1, -1, -1};
            for (int c = 0; c < 3; ++c) {
                const std::string_view corner = tokens[c + 1];
                const std::size_t slash = corner.find('/');
                const std::string_view v = corner.substr(0, slash);
                faces.push_back(resolve_index(reader, v, vertex_count, "vertex"));
                if (slash == std::string_view::npos) continue;
                const std::string_view rest = corner.substr(slash + 1);
                const std::size_t slash2 = rest.find('/');
                const std::string_view t = rest.substr(0, slash2);
                if (slash2 != std::string_view::npos) {
                    const std::string_view n = rest.substr(slash2 + 1);
                    if (n.find('/') != std::string_view::npos)
                        reader.fail("bad face corner " + io::quote(corner));
                    if (!n.empty()) reader.to_integer(n, "normal index");
                }
                if (!t.empty()) {
                    corner_uv[c] = resolve_index(reader, t, uv_count, "texture coordinate");
                    ++with_uv;
                }
            }
            if (with_uv != 0 && with_uv != 3)
                reader.fail("face mixes corners with and without texture coordinates");
            if (first_face_line == 0) {
                first_face_line = reader.line_number();
                faces_have_uv = with_uv == 3;
            } else if (faces_have_uv != (with_uv == 3)) {
                reader.fail(std::string("face ") + (with_uv == 3 ? "with" : "without") +
                            " texture coordinates, but the face on line " +
                            std::to_string(first_face_line) +
                            (faces_have_uv ? " has them" : " has none") +
                            " (all faces need them or none)");
            }
            face_lines.push_back(reader.line_number());
            if (with_uv == 3) face_uvs.insert(face_uvs.end(), corner_uv.begin(), corner_uv.end());
        }
        // vn, vp, g, o, s, l, usemtl, mtllib and unknown keywords: ignored.
    }

    const int dims = (vertex_count > 0 && !any_3d) ? 2 : 3;
    if (any_3d && first_2d_line != 0) {
        result.warnings.push_back(path + ":" + std::to_string(first_2d_line) +
                                  ": vertex with 2 coordinates among 3D vertices; z = 0");
    }
    auto& mesh = result.mesh;
    mesh.vertices.resize(vertex_count, dims);
    for (int i = 0; i < vertex_count; ++i)
        for (int j = 0; j < dims; ++j) mesh.vertices(i, j) = coordinates[3 * i + j];
    const int face_count = static_cast<int>(faces.size() / 3);
    mesh.simplices.resize(face_count, 3);
    for (int f = 0; f < face_count; ++f)
        for (int c = 0; c < 3; ++c) mesh.simplices(f, c) = faces[3 * f + c];

    if (uv_count > 0) {
        result.texture_coordinates.resize(uv_count, 2);
        for (int i = 0; i < uv_count; ++i)
            for (int j = 0; j < 2; ++j) result.texture_coordinates(i, j) = uvs[2 * i + j];
    }
    if (!faces_have_uv || face_count == 0) return result;

    result.face_texture_indices.resize(face_count, 3);
    for (int f = 0; f < face_count; ++f)
        for (int c = 0; c < 3; ++c) result.face_texture_indices(f, c) = face_uvs[3 * f + c];

    // Per-vertex uv: each vertex must get one value through all of its corners.
    std::vector<int> first_face(vertex_count, -1);
    Eigen::MatrixXd initial(vertex_count, 2);
    for (int f = 0; f < face_count; ++f) {
        for (int c = 0; c < 3; ++c) {
            const int v = faces[3 * f + c];
            const int t = face_uvs[3 * f + c];
            const double u = uvs[2 * t], w = uvs[2 * t + 1];
            if (first_face[v] < 0) {
                first_face[v] = f;
                initial(v, 0) = u;
                initial(v, 1) = w;
            } else if (initial(v, 0) != u || initial(v, 1) != w) {
                result.warnings.push_back(
                    path + ": vertex " + std::to_string(v + 1) + " has two texture coordinates, " +
                    format_uv(initial(v, 0), initial(v, 1)) + " on line " +
                    std::to_string(face_lines[first_face[v]]) + " and " + format_uv(u, w) +
                    " on line " + std::to_string(face_lines[f]) + "; no per-vertex initial map");
                return result;
            }
        }
    }
    for (int v = 0; v < vertex_count; ++v) {
        if (first_face[v] < 0) {
            result.warnings.push_back(path + ": vertex " + std::to_string(v + 1) +
                                      " is in no face, so it has no texture coordinate; no "
                                      "per-vertex initial map");
            return result;
        }
    }
    result.initial = std::move(initial);
    return result;
}

void write_obj(const std::string& path, const Eigen::MatrixXd& positions,
               const Eigen::MatrixXi& triangles, const Eigen::MatrixXd* texture_coordinates,
               const Eigen::MatrixXi* face_texture_indices) {
    constexpr const char* kFunction = "write_obj";
    io::check_positions(kFunction, positions);
    io::check_simplices(kFunction, "triangles", triangles, positions.rows(), 3);
    if (face_texture_indices != nullptr && texture_coordinates == nullptr)
        throw InvalidArgumentError(std::string(kFunction) +
                                   ": face_texture_indices given without texture_coordinates");
    if (texture_coordinates != nullptr) {
        io::check_positions(kFunction, *texture_coordinates, 2, 2);
        if (face_texture_indices != nullptr) {
            if (face_texture_indices->rows() != triangles.rows())
                throw InvalidArgumentError(std::string(kFunction) + ": face_texture_indices has " +
                                           std::to_string(face_texture_indices->rows()) +
                                           " rows, triangles " + std::to_string(triangles.rows()));
            io::check_simplices(kFunction, "face_texture_indices", *face_texture_indices,
                                texture_coordinates->rows(), 3);
        } else if (texture_coordinates->rows() != positions.rows()) {
            throw InvalidArgumentError(std::string(kFunction) + ": texture_coordinates has " +
                                       std::to_string(texture_coordinates->rows()) +
                                       " rows, positions " + std::to_string(positions.rows()) +
                                       " (without face_texture_indices they must match)");
        }
    }

    AtomicFile file(path);
    std::ostream& out = file.stream();
    for (Eigen::Index i = 0; i < positions.rows(); ++i) {
        out << "v ";
        io::write_position(out, positions, i, true);
        out << '\n';
    }
    if (texture_coordinates != nullptr) {
        for (Eigen::Index i = 0; i < texture_coordinates->rows(); ++i) {
            out << "vt ";
            io::write_position(out, *texture_coordinates, i, false);
            out << '\n';
        }
    }
    for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
        out << 'f';
        for (int c = 0; c < 3; ++c) {
            out << ' ' << triangles(f, c) + 1;
            if (texture_coordinates != nullptr) {
                const int t = face_texture_indices != nullptr ? (*face_texture_indices)(f, c)
                                                              : triangles(f, c);
                out << '/' << t + 1;
            }
        }
        out << '\n';
    }
    file.commit();
}

}  // namespace sa
