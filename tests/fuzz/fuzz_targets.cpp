#include "fuzz_targets.h"

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "geometry/io/dmat_io.h"
#include "geometry/io/frame_field_io.h"
#include "geometry/io/index_list_io.h"
#include "geometry/io/indexed_positions_io.h"
#include "geometry/io/medit_io.h"
#include "geometry/io/obj_io.h"
#include "geometry/io/off_io.h"
#include "geometry/io/openmesh_io.h"
#include "geometry/io/ply_io.h"
#include "geometry/io/polycube_labels_io.h"
#include "geometry/io/problem_io.h"
#include "geometry/io/rawfield_io.h"
#include "geometry/io/tetgen_io.h"
#include "geometry/io/vtk_io.h"
#include "geometry/mesh/mesh_generators.h"
#include "optim/errors.h"

namespace sa::fuzz {
namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// Inputs as files: in a folder of the process's own, on /dev/shm when there is one (a memory file
// system: no disk traffic at thousands of inputs a second), removed at exit.

const fs::path& folder() {
    static const fs::path path = [] {
        std::error_code error;
        const fs::path base =
            fs::is_directory("/dev/shm", error) ? fs::path("/dev/shm") : fs::temp_directory_path();
        fs::path p = base / ("sa_fuzz_" + std::to_string(getpid()));
        fs::create_directories(p);
        std::atexit([] {
            std::error_code ignored;
            fs::remove_all(folder(), ignored);
        });
        return p;
    }();
    return path;
}

/// Writes `size` bytes to `name` in the folder; returns its path.
std::string write(const std::string& name, const std::uint8_t* data, std::size_t size) {
    const std::string path = (folder() / name).string();
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path;
}

/// The position of the first NUL byte, or `size`.
std::size_t split(const std::uint8_t* data, std::size_t size) {
    const auto* nul = static_cast<const std::uint8_t*>(std::memchr(data, 0, size));
    return nul == nullptr ? size : static_cast<std::size_t>(nul - data);
}

Bytes bytes(const std::string& text) {
    return Bytes(text.begin(), text.end());
}

/// What a writer of the project puts in a file.
template <class Write>
Bytes written(const std::string& name, Write&& write_file) {
    const std::string path = (folder() / ("seed-" + name)).string();
    write_file(path);
    std::ifstream in(path, std::ios::binary);
    Bytes content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    fs::remove(path);
    return content;
}

Bytes joined(Bytes a, const Bytes& b) {
    a.push_back(0);
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

Bytes with_trailer(Bytes a, std::initializer_list<std::uint8_t> trailer) {
    a.insert(a.end(), trailer);
    return a;
}

Bytes with_crlf(const Bytes& a) {
    Bytes out;
    for (const std::uint8_t c : a) {
        if (c == '\n') out.push_back('\r');
        out.push_back(c);
    }
    return out;
}

// Small meshes the seeds are made of.
const SimplicialMesh& triangles() {
    static const SimplicialMesh mesh = grid_triangles(2, 2);
    return mesh;
}
const SimplicialMesh& tetrahedra() {
    static const SimplicialMesh mesh = grid_tetrahedra(1, 1, 1);
    return mesh;
}
Eigen::MatrixXd lifted(const SimplicialMesh& mesh) {
    Eigen::MatrixXd p = Eigen::MatrixXd::Zero(mesh.num_vertices(), 3);
    p.leftCols(mesh.vertices.cols()) = mesh.vertices;
    for (Index v = 0; v < mesh.num_vertices(); ++v) p(v, 2) = 0.1 * double(v % 3);
    return p;
}

std::string problem_text(const SimplicialMesh& mesh, const Eigen::MatrixXd& rest,
                         const Eigen::MatrixXd& initial, const std::vector<int>& handles) {
    std::ostringstream out;
    out.precision(17);
    out << rest.rows() << ' ' << rest.cols() << "\n" << rest << "\n";
    out << initial.rows() << ' ' << initial.cols() << "\n" << initial << "\n";
    out << mesh.num_simplices() << ' ' << mesh.simplices.cols() << "\n" << mesh.simplices << "\n";
    if (!handles.empty()) {
        out << handles.size() << "\n";
        for (int h : handles) out << h << ' ';
        out << "\n";
    }
    return out.str();
}

// ---------------------------------------------------------------------------------------------
// The targets.

void run_problem(const std::uint8_t* data, std::size_t size) {
    read_problem(write("input", data, size));
}
std::vector<Bytes> seeds_problem() {
    const SimplicialMesh& t = triangles();
    Eigen::MatrixXd folded = t.vertices;
    folded(4, 0) = 1.4;
    const Bytes planar = bytes(problem_text(t, t.vertices, folded, {0, 2, 6, 8}));
    return {planar, with_crlf(planar),
            bytes("# a comment\n" + problem_text(t, lifted(t), t.vertices, {0, 1})),
            bytes(problem_text(tetrahedra(), tetrahedra().vertices, tetrahedra().vertices, {})),
            bytes("\xEF\xBB\xBF" + problem_text(t, t.vertices, t.vertices, {3}))};
}

void run_result_records(const std::uint8_t* data, std::size_t size) {
    read_result_positions(write("result", data, size));
}
std::vector<Bytes> seeds_result_records() {
    const Bytes records = written(
        "result", [](const std::string& p) { write_result_records(p, lifted(triangles())); });
    return {records, bytes("iterations 1\n12\nresV 2 2\n0 0.5 1 -1e-3\n"), bytes("resV 0 3\n")};
}

void run_obj(const std::uint8_t* data, std::size_t size) {
    read_obj(write("mesh.obj", data, size));
}
std::vector<Bytes> seeds_obj() {
    const SimplicialMesh& t = triangles();
    const Eigen::MatrixXd uv = t.vertices * 0.5;
    return {
        written("a.obj", [&](const std::string& p) { write_obj(p, lifted(t), t.simplices); }),
        written("b.obj", [&](const std::string& p) { write_obj(p, lifted(t), t.simplices, &uv); }),
        bytes("# negative indices, normals, groups\nv 0 0 0\nv 1 0 0\nv 0 1\nvn 0 0 1\ng a\n"
              "vt 0 0\nvt 1 0\nvt 0 1\nf -3/-3/1 -2/-2/1 -1/-1/1\nusemtl m\ns off\n")};
}

void run_off(const std::uint8_t* data, std::size_t size) {
    read_off(write("mesh.off", data, size));
}
std::vector<Bytes> seeds_off() {
    const SimplicialMesh& t = triangles();
    const Bytes off =
        written("a.off", [&](const std::string& p) { write_off(p, lifted(t), t.simplices); });
    return {off, with_crlf(off),
            bytes("COFF 3 1 3\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n"
                  "3 0 1 2 0.5 0.5 0.5\n")};
}

void run_medit(const std::uint8_t* data, std::size_t size) {
    read_medit(write("mesh.mesh", data, size));
}
std::vector<Bytes> seeds_medit() {
    const SimplicialMesh& t = triangles();
    const SimplicialMesh& tets = tetrahedra();
    return {
        written("a.mesh", [&](const std::string& p) { write_medit(p, t.vertices, t.simplices); }),
        written("b.mesh",
                [&](const std::string& p) { write_medit(p, tets.vertices, tets.simplices); }),
        bytes("MeshVersionFormatted 1\nDimension\n3\nVertices\n3\n0 0 0 1\n1 0 0 1\n0 1 0 1\n"
              "Edges\n1\n1 2 0\nCorners\n1\n1\nTriangles\n1\n1 2 3 7\nEnd\n")};
}

void run_tetgen(const std::uint8_t* data, std::size_t size) {
    const std::size_t at = split(data, size);
    write("mesh.ele", data + std::min(at + 1, size), size - std::min(at + 1, size));
    read_tetgen(write("mesh.node", data, at));
}
std::vector<Bytes> seeds_tetgen() {
    const SimplicialMesh& tets = tetrahedra();
    const std::string path = (folder() / "seed.node").string();
    write_tetgen(path, tets.vertices, tets.simplices);
    auto slurp = [](const std::string& p) {
        std::ifstream in(p, std::ios::binary);
        return Bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    const Bytes node = slurp(path), ele = slurp((folder() / "seed.ele").string());
    fs::remove(path);
    fs::remove(folder() / "seed.ele");
    return {joined(node, ele),
            joined(bytes("4 3 1 1\n1 0 0 0 7 1\n2 1 0 0 7 1\n3 0 1 0 7 0\n4 0 0 1 7 0\n"),
                   bytes("# one tet, 1-based\n1 4 1\n1 1 2 3 4 9\n"))};
}

void run_vtk(const std::uint8_t* data, std::size_t size) {
    read_vtk(write("mesh.vtk", data, size));
}
std::vector<Bytes> seeds_vtk() {
    const SimplicialMesh& t = triangles();
    const SimplicialMesh& tets = tetrahedra();
    const std::vector<DataArray> point_data = {{"u", Eigen::MatrixXd::Ones(t.num_vertices(), 2)}};
    // A BINARY file in the version 5 layout: big-endian values of `bytes` bytes each.
    const auto big_endian = [](std::initializer_list<std::uint64_t> values, int bytes) {
        std::string text;
        for (const std::uint64_t value : values) {
            for (int b = bytes - 1; b >= 0; --b) text.push_back(static_cast<char>(value >> 8 * b));
        }
        return text;
    };
    const std::uint64_t one = 0x3f800000;  // 1.0f
    const std::string binary_vtk =
        "# vtk DataFile Version 5.1\nb\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 3 float\n" +
        big_endian({0, 0, 0, one, 0, 0, 0, one, 0}, 4) + "\nCELLS 2 3\nOFFSETS vtktypeint64\n" +
        big_endian({0, 3}, 8) + "\nCONNECTIVITY vtktypeint64\n" + big_endian({0, 1, 2}, 8) +
        "\nCELL_TYPES 1\n" + big_endian({5}, 4) + "\n";
    return {
        written("a.vtk",
                [&](const std::string& p) { write_vtk(p, t.vertices, t.simplices, point_data); }),
        written("b.vtk",
                [&](const std::string& p) { write_vtk(p, tets.vertices, tets.simplices); }),
        bytes("# vtk DataFile Version 3.0\npoly\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n"
              "0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 2\n"),
        bytes(binary_vtk)};
}

void run_dmat(const std::uint8_t* data, std::size_t size) {
    read_dmat(write("matrix.dmat", data, size));
}
std::vector<Bytes> seeds_dmat() {
    Eigen::MatrixXd m(3, 2);
    m << 1, -2, 0.5, 1e-3, 7, 1e10;
    Bytes binary = bytes("0 0\n2 3\n");
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
        for (Eigen::Index i = 0; i < m.rows(); ++i) {
            std::uint8_t b[8];
            const double value = m(i, j);
            std::memcpy(b, &value, 8);
            binary.insert(binary.end(), b, b + 8);
        }
    }
    return {written("a.dmat", [&](const std::string& p) { write_dmat(p, m); }), binary,
            bytes("0 0\n")};
}

void run_frame_field(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return;
    const Index faces = data[size - 2];
    const int reader = data[size - 1] % 3;
    size -= 2;
    if (reader == 0) {
        read_frame_field(write("field.crossfield", data, size), faces);
    } else if (reader == 1) {
        read_frame_field(write("field.dmat", data, size), faces);
    } else {
        const std::size_t at = split(data, size);
        const std::string bc =
            write("bc.dmat", data + std::min(at + 1, size), size - std::min(at + 1, size));
        read_frame_field_constraints(write("b.dmat", data, at), bc, faces);
    }
}
std::vector<Bytes> seeds_frame_field() {
    Eigen::MatrixXd dense(4, 6);
    dense << 1, 0, 0, 0, 1, 0, 0, 1, 0, -1, 0, 0, 1, 1, 0, -1, 1, 0, 0, 0, 1, 0, 1, 1;
    Eigen::MatrixXd b(2, 1), bc(2, 3);
    b << 0, 3;
    bc << 1, 0, 0, 0, 0, 1;
    auto dmat = [](const Eigen::MatrixXd& m) {
        return written("f.dmat", [&](const std::string& p) { write_dmat(p, m); });
    };
    return {with_trailer(bytes("2 3\n1 1 0 0 0 1 0\n0 0 0 0 0 0 0\n1 0 0 1 0 1 0\n"), {3, 0}),
            with_trailer(dmat(dense), {4, 1}), with_trailer(joined(dmat(b), dmat(bc)), {4, 2})};
}

void run_rawfield(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return;
    read_rawfield(write("field.rawfield", data, size - 1), data[size - 1]);
}
std::vector<Bytes> seeds_rawfield() {
    const Bytes field = bytes(
        "4 3\n1 0 0 0 1 0 -1 0 0 0 -1 0\n0 0 0 0 0 0 0 0 0 0 0 0\n"
        "0.5 0.5 0 -2 2 0 -0.5 -0.5 0 2 -2 0\n");
    return {with_trailer(field, {3}), with_trailer(with_crlf(field), {3}),
            with_trailer(bytes("4 1\n0 1e-3 0 1 0 0 0 -1e-3 0 -1 0 0\n"), {1})};
}

void run_indexed_positions(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return;
    // The last byte: its low bit the dimension (2 or 3), the rest the vertex count plus one (0:
    // no range check).
    const std::uint8_t b = data[size - 1];
    // Both layouts, as deform/handle_targets.h reads them; refused when neither reads it.
    const std::string path = write("targets.txt", data, size - 1);
    const int dimension = 2 + (b & 1);
    std::exception_ptr refused;
    try {
        read_position_rows(path, dimension, Index(b >> 1) - 1);
    } catch (const sa::Error&) {
        refused = std::current_exception();
    }
    try {
        read_position_rows(path, dimension, Index(b >> 1) - 1, RowLayout::plain);
    } catch (const sa::Error&) {
        if (refused) std::rethrow_exception(refused);
    }
}
std::vector<Bytes> seeds_indexed_positions() {
    return {with_trailer(bytes("2\n0 0.5 0.5 0\n3 1 2 3 # moved\n"), {1 + 2 * 5}),
            with_trailer(bytes("0 1 1\r\n4 -1 2.5e3\r\n0 1 1\r\n"), {0 + 2 * 9}),
            with_trailer(bytes("# plain\n0 0\n1 0\n0 1\n"), {0}),
            with_trailer(bytes("1 2 3\n4 5 6\n"), {1}),
            with_trailer(bytes("2\n1.5 2 0\n4 5 0\n"), {0 + 2 * 6})};
}

void run_polycube_labels(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return;
    // The last two bytes: the element count, then the reader (even: .flags, odd: labeling.txt).
    const Index count = data[size - 2];
    const std::string path = write("labels.txt", data, size - 2);
    if (data[size - 1] % 2 == 0)
        read_facet_flags(path, count);
    else
        read_triangle_labels(path, count);
}
std::vector<Bytes> seeds_polycube_labels() {
    const Bytes flags = written("a.flags", [](const std::string& p) {
        write_facet_flags(p, {-1, 0, 2, 5, 1, -1, -1, 4});
    });
    return {with_trailer(flags, {2, 0}), with_trailer(bytes("0 1 2 3\n4 5\r\n"), {6, 1}),
            with_trailer(bytes("-1 -1 -1 3\n"), {1, 0})};
}

void run_index_list(const std::uint8_t* data, std::size_t size) {
    read_index_list(write("handles.txt", data, size));
}
std::vector<Bytes> seeds_index_list() {
    return {written("h.txt",
                    [](const std::string& p) {
                        write_index_list(p, {3, 1, 4, 15});
                    }),
            bytes("3 #Vertices Locked\n0\n1\n2\n"), bytes("3 10 20 30\n"),
            bytes("11216\r\n11253\r\n# end\r\n")};
}

void run_ply_stl(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return;
    const bool stl = data[size - 1] % 2 == 1;
    if (stl)
        read_stl(write("mesh.stl", data, size - 1));
    else
        read_ply(write("mesh.ply", data, size - 1));
}
std::vector<Bytes> seeds_ply_stl() {
    const std::string ply_header =
        "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    Bytes binary_ply = bytes("ply\nformat binary_little_endian 1.0\n" + ply_header);
    const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const auto* c = reinterpret_cast<const std::uint8_t*>(corners);
    binary_ply.insert(binary_ply.end(), c, c + sizeof corners);
    const std::int32_t face[3] = {0, 1, 2};
    binary_ply.push_back(3);
    const auto* f = reinterpret_cast<const std::uint8_t*>(face);
    binary_ply.insert(binary_ply.end(), f, f + sizeof face);

    Bytes binary_stl(80, ' ');
    const std::uint32_t count = 1;
    const auto* n = reinterpret_cast<const std::uint8_t*>(&count);
    binary_stl.insert(binary_stl.end(), n, n + 4);
    const float facet[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
    const auto* t = reinterpret_cast<const std::uint8_t*>(facet);
    binary_stl.insert(binary_stl.end(), t, t + sizeof facet);
    binary_stl.push_back(0);
    binary_stl.push_back(0);
    return {with_trailer(bytes("ply\nformat ascii 1.0\n" + ply_header +
                               "0 0 0\n1 0 0\n0 1 0\n"
                               "3 0 1 2\n"),
                         {0}),
            with_trailer(binary_ply, {0}),
            with_trailer(bytes("solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0"
                               "\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n"),
                         {1}),
            with_trailer(binary_stl, {1})};
}

}  // namespace

const std::vector<Target>& targets() {
    static const std::vector<Target> all = {
        {"problem", run_problem, seeds_problem},
        {"result_records", run_result_records, seeds_result_records},
        {"obj", run_obj, seeds_obj},
        {"off", run_off, seeds_off},
        {"medit", run_medit, seeds_medit},
        {"tetgen", run_tetgen, seeds_tetgen},
        {"vtk", run_vtk, seeds_vtk},
        {"dmat", run_dmat, seeds_dmat},
        {"frame_field", run_frame_field, seeds_frame_field},
        {"rawfield", run_rawfield, seeds_rawfield},
        {"index_list", run_index_list, seeds_index_list},
        {"ply_stl", run_ply_stl, seeds_ply_stl},
        {"indexed_positions", run_indexed_positions, seeds_indexed_positions},
        {"polycube_labels", run_polycube_labels, seeds_polycube_labels},
    };
    return all;
}

const Target& target(const std::string& name) {
    for (const Target& t : targets()) {
        if (name == t.name) return t;
    }
    throw std::invalid_argument("no fuzz target '" + name + "'");
}

}  // namespace sa::fuzz
