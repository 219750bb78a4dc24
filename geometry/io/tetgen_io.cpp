#include "geometry/io/tetgen_io.h"

#include <string>

#include "geometry/io/atomic_file.h"
#include "geometry/io/text_reader.h"
#include "geometry/io/write_checks.h"
#include "optim/errors.h"

namespace sa {
namespace {

std::string plural(long long n, const char* word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

// Reads a row's index: the first row sets the numbering base (0 or 1), later rows must follow.
void check_row_index(const io::TextReader& reader, std::string_view token, int row, int& base) {
    const long long index = reader.to_integer(token, "row index");
    if (row == 0) {
        if (index != 0 && index != 1)
            reader.fail("first row index is " + std::to_string(index) + "; expected 0 or 1");
        base = static_cast<int>(index);
    } else if (index != row + base) {
        reader.fail("row index " + std::to_string(index) + " out of sequence; expected " +
                    std::to_string(row + base));
    }
}

// Reads the .node file; returns its numbering base.
int read_node(const std::string& path, Eigen::MatrixXd& vertices) {
    io::TextReader reader(path);
    if (!reader.next_line()) reader.fail_file("empty file; expected '#V dim #attributes #markers'");
    const auto& header = reader.tokens();
    if (header.size() != 4)
        reader.fail("expected 4 numbers (#V dim #attributes #markers) in the header, found " +
                    std::to_string(header.size()));
    const int n = reader.to_count(header[0], "vertex count");
    const int dim = reader.to_count(header[1], "dimension");
    const int attributes = reader.to_count(header[2], "attribute count");
    const int markers = reader.to_count(header[3], "marker count");
    if (dim != 3) reader.fail("dimension " + std::to_string(dim) + "; only 3 is supported");
    if (markers > 1) reader.fail("marker count " + std::to_string(markers) + "; expected 0 or 1");
    const std::size_t expected =
        4 + static_cast<std::size_t>(attributes) + static_cast<std::size_t>(markers);
    std::string layout = "index x y z";
    if (attributes > 0) layout += ", " + plural(attributes, "attribute");
    if (markers > 0) layout += ", marker";

    const long long rows = reader.fitting(n, static_cast<long long>(expected));
    vertices.resize(rows, 3);
    int base = 0;
    for (int i = 0; i < n; ++i) {
        if (!reader.next_line())
            reader.fail_file("file ends after " + std::to_string(i) + " of " + std::to_string(n) +
                             " vertex rows");
        const auto& tokens = reader.tokens();
        if (tokens.size() != expected)
            reader.fail("expected " + std::to_string(expected) + " numbers (" + layout +
                        "), found " + std::to_string(tokens.size()));
        check_row_index(reader, tokens[0], i, base);
        reader.check_room(i, rows, "vertex rows");
        for (int j = 0; j < 3; ++j) vertices(i, j) = reader.to_double(tokens[j + 1], "coordinate");
        for (std::size_t j = 4; j < tokens.size(); ++j) reader.to_double(tokens[j], "attribute");
    }
    if (reader.next_line())
        reader.fail("unexpected data after the " + plural(n, "vertex row") +
                    " declared in the header");
    return base;
}

void read_ele(const std::string& path, int node_base, int num_vertices, Eigen::MatrixXi& tets) {
    io::TextReader reader(path);
    if (!reader.next_line()) reader.fail_file("empty file; expected '#T k #attributes'");
    const auto& header = reader.tokens();
    if (header.size() != 3)
        reader.fail("expected 3 numbers (#T k #attributes) in the header, found " +
                    std::to_string(header.size()));
    const int m = reader.to_count(header[0], "element count");
    const int k = reader.to_count(header[1], "nodes per element");
    const int attributes = reader.to_count(header[2], "attribute count");
    if (k != 4)
        reader.fail(std::to_string(k) + " nodes per element; only 4-node tetrahedra are supported");
    const std::size_t expected = 5 + static_cast<std::size_t>(attributes);
    std::string layout = "index a b c d";
    if (attributes > 0) layout += ", " + plural(attributes, "attribute");

    const long long rows = reader.fitting(m, static_cast<long long>(expected));
    tets.resize(rows, 4);
    int base = 0;
    const long long low = node_base, high = static_cast<long long>(num_vertices) - 1 + node_base;
    for (int e = 0; e < m; ++e) {
        if (!reader.next_line())
            reader.fail_file("file ends after " + std::to_string(e) + " of " + std::to_string(m) +
                             " tetrahedra");
        const auto& tokens = reader.tokens();
        if (tokens.size() != expected)
            reader.fail("expected " + std::to_string(expected) + " numbers (" + layout +
                        "), found " + std::to_string(tokens.size()));
        check_row_index(reader, tokens[0], e, base);
        reader.check_room(e, rows, "tetrahedra");
        for (int c = 0; c < 4; ++c) {
            const long long v = reader.to_integer(tokens[c + 1], "vertex index");
            if (v < low || v > high)
                reader.fail("vertex " + std::to_string(v) + " out of range [" +
                            std::to_string(low) + ", " + std::to_string(high) + "]");
            tets(e, c) = static_cast<int>(v - node_base);
        }
        for (std::size_t j = 5; j < tokens.size(); ++j) reader.to_double(tokens[j], "attribute");
    }
    if (reader.next_line())
        reader.fail("unexpected data after the " + std::to_string(m) +
                    " tetrahedra declared in the header");
}

}  // namespace

MeshFile read_tetgen(const std::string& path) {
    const std::string extension = io::lower_extension(path);
    if (extension != ".node" && extension != ".ele")
        throw InvalidArgumentError("read_tetgen: " + path + ": expected a .node or .ele file name");
    const std::string node_path =
        extension == ".node" ? path : io::replace_extension(path, ".node");
    const std::string ele_path = extension == ".ele" ? path : io::replace_extension(path, ".ele");
    MeshFile result;
    const int base = read_node(node_path, result.mesh.vertices);
    read_ele(ele_path, base, static_cast<int>(result.mesh.vertices.rows()), result.mesh.simplices);
    return result;
}

void write_tetgen(const std::string& path, const Eigen::MatrixXd& positions,
                  const Eigen::MatrixXi& tets) {
    constexpr const char* kFunction = "write_tetgen";
    const std::string extension = io::lower_extension(path);
    if (extension != ".node" && extension != ".ele")
        throw InvalidArgumentError(std::string(kFunction) + ": " + path +
                                   ": expected a .node or .ele file name");
    io::check_positions(kFunction, positions, 3, 3);
    io::check_simplices(kFunction, "tets", tets, positions.rows(), 4);
    const std::string node_path =
        extension == ".node" ? path : io::replace_extension(path, ".node");
    const std::string ele_path = extension == ".ele" ? path : io::replace_extension(path, ".ele");

    AtomicFile node(node_path);
    AtomicFile ele(ele_path);
    std::ostream& nodes = node.stream();
    nodes << positions.rows() << " 3 0 0\n";
    for (Eigen::Index i = 0; i < positions.rows(); ++i) {
        nodes << i << ' ';
        io::write_position(nodes, positions, i, false);
        nodes << '\n';
    }
    std::ostream& elements = ele.stream();
    elements << tets.rows() << " 4 0\n";
    for (Eigen::Index e = 0; e < tets.rows(); ++e)
        elements << e << ' ' << tets(e, 0) << ' ' << tets(e, 1) << ' ' << tets(e, 2) << ' '
                 << tets(e, 3) << '\n';
    node.commit();
    ele.commit();
}

}  // namespace sa
