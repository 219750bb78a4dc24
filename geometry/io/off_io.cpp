#include "geometry/io/off_io.h"

#include <string>

#include "geometry/io/atomic_file.h"
#include "geometry/io/text_reader.h"
#include "geometry/io/write_checks.h"

namespace sa {

MeshFile read_off(const std::string& path) {
    io::TextReader reader(path);
    if (!reader.next_line()) reader.fail_file("empty file; expected the header 'OFF'");
    const std::string_view header = reader.tokens()[0];
    if (header != "OFF" && header != "COFF" && header != "NOFF" && header != "CNOFF") {
        if (header.find("OFF") != std::string_view::npos)
            reader.fail("unsupported OFF variant " + io::quote(header) +
                        "; only OFF, COFF, NOFF and CNOFF are supported");
        reader.fail("expected the header 'OFF', found " + io::quote(header));
    }
    const bool plain = header == "OFF";
    std::size_t first = 1;  // the counts may follow the header on its line
    if (reader.tokens().size() == 1) {
        if (!reader.next_line()) reader.fail_file("file ends before the counts '#V #F #E'");
        first = 0;
    }
    const auto& counts = reader.tokens();
    if (counts.size() > first && counts[first] == "BINARY")
        reader.fail("binary OFF is not supported; only ASCII");
    if (counts.size() - first < 2 || counts.size() - first > 3)
        reader.fail("expected the counts '#V #F #E', found " +
                    std::to_string(counts.size() - first) + " values");
    const int num_vertices = reader.to_count(counts[first], "vertex count");
    const int num_faces = reader.to_count(counts[first + 1], "face count");
    if (counts.size() - first == 3) reader.to_count(counts[first + 2], "edge count");

    MeshFile result;
    auto& mesh = result.mesh;
    const long long vertex_rows = reader.fitting(num_vertices, 3);
    mesh.vertices.resize(vertex_rows, 3);
    for (int i = 0; i < num_vertices; ++i) {
        if (!reader.next_line())
            reader.fail_file("file ends after " + std::to_string(i) + " of " +
                             std::to_string(num_vertices) + " vertices");
        const auto& tokens = reader.tokens();
        if (tokens.size() < 3 || (plain && tokens.size() != 3))
            reader.fail("expected 3 numbers (x y z) for vertex " + std::to_string(i) + ", found " +
                        std::to_string(tokens.size()));
        reader.check_room(i, vertex_rows, "vertices");
        for (std::size_t j = 0; j < tokens.size(); ++j) {
            const double value = reader.to_double(tokens[j], "coordinate");
            if (j < 3) mesh.vertices(i, static_cast<Eigen::Index>(j)) = value;
        }
    }
    const long long face_rows = reader.fitting(num_faces, 4);
    mesh.simplices.resize(face_rows, 3);
    for (int f = 0; f < num_faces; ++f) {
        if (!reader.next_line())
            reader.fail_file("file ends after " + std::to_string(f) + " of " +
                             std::to_string(num_faces) + " faces");
        const auto& tokens = reader.tokens();
        const int k = reader.to_count(tokens[0], "face vertex count");
        if (k != 3)
            reader.fail("face with " + std::to_string(k) +
                        " vertices; only triangles are supported");
        if (tokens.size() < 4)
            reader.fail("expected 4 numbers (3 a b c) for face " + std::to_string(f) + ", found " +
                        std::to_string(tokens.size()));
        reader.check_room(f, face_rows, "faces");
        for (int c = 0; c < 3; ++c) {
            const long long v = reader.to_integer(tokens[c + 1], "vertex index");
            if (v < 0 || v >= num_vertices)
                reader.fail("vertex " + std::to_string(v) + " out of range [0, " +
                            std::to_string(num_vertices - 1) + "]");
            mesh.simplices(f, c) = static_cast<int>(v);
        }
        for (std::size_t j = 4; j < tokens.size(); ++j) reader.to_double(tokens[j], "colour value");
    }
    if (reader.next_line())
        reader.fail("unexpected data after the " + std::to_string(num_faces) +
                    " faces declared in the header");
    return result;
}

void write_off(const std::string& path, const Eigen::MatrixXd& positions,
               const Eigen::MatrixXi& triangles) {
    io::check_positions("write_off", positions);
    io::check_simplices("write_off", "triangles", triangles, positions.rows(), 3);
    AtomicFile file(path);
    std::ostream& out = file.stream();
    out << "OFF\n" << positions.rows() << ' ' << triangles.rows() << " 0\n";
    for (Eigen::Index i = 0; i < positions.rows(); ++i) {
        io::write_position(out, positions, i, true);
        out << '\n';
    }
    for (Eigen::Index f = 0; f < triangles.rows(); ++f)
        out << "3 " << triangles(f, 0) << ' ' << triangles(f, 1) << ' ' << triangles(f, 2) << '\n';
    file.commit();
}

}  // namespace sa
