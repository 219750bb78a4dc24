#include "geometry/io/problem_io.h"

#include <string>
#include <unordered_map>
#include <vector>

#include "geometry/io/atomic_file.h"
#include "geometry/io/text_reader.h"
#include "geometry/io/write_checks.h"

namespace sa {
namespace {

// Reads a header line `count columns`.
void read_header(io::TextReader& reader, const char* what, const char* layout, int& count,
                 int& columns) {
    if (!reader.next_line())
        reader.fail_file(std::string("file ends before the ") + what + " header '" + layout + "'");
    const auto& tokens = reader.tokens();
    if (tokens.size() != 2)
        reader.fail(std::string("expected the ") + what + " header '" + layout + "', found " +
                    std::to_string(tokens.size()) + " values");
    count = reader.to_count(tokens[0], "count");
    columns = reader.to_count(tokens[1], "column count");
}

Eigen::MatrixXd read_positions(io::TextReader& reader, const char* what, int count, int dim) {
    const long long allocated = reader.fitting(count, dim);
    Eigen::MatrixXd positions(allocated, dim);
    for (int i = 0; i < count; ++i) {
        if (!reader.next_line())
            reader.fail_file("file ends after " + std::to_string(i) + " of " +
                             std::to_string(count) + " " + what);
        const auto& tokens = reader.tokens();
        if (static_cast<int>(tokens.size()) != dim)
            reader.fail("expected " + std::to_string(dim) + " coordinates for vertex " +
                        std::to_string(i) + ", found " + std::to_string(tokens.size()));
        reader.check_room(i, allocated, what);
        for (int j = 0; j < dim; ++j) positions(i, j) = reader.to_double(tokens[j], "coordinate");
    }
    return positions;
}

}  // namespace

MeshFile read_problem(const std::string& path) {
    io::TextReader reader(path);
    MeshFile result;
    auto& mesh = result.mesh;

    int num_vertices = 0, dim = 0;
    read_header(reader, "rest positions", "#V dim", num_vertices, dim);
    if (dim != 2 && dim != 3)
        reader.fail("rest dimension " + std::to_string(dim) + "; expected 2 or 3");
    mesh.vertices = read_positions(reader, "rest positions", num_vertices, dim);

    int num_initial = 0, dim2 = 0;
    read_header(reader, "initial positions", "#V dim", num_initial, dim2);
    if (num_initial != num_vertices)
        reader.fail(std::to_string(num_initial) + " initial positions for " +
                    std::to_string(num_vertices) + " rest vertices");
    if (dim2 != 2 && dim2 != 3)
        reader.fail("initial dimension " + std::to_string(dim2) + "; expected 2 or 3");
    const int initial_header = reader.line_number();
    result.initial = read_positions(reader, "initial positions", num_vertices, dim2);
    if (dim == 2 && dim2 == 3) {
        // A planar rest shape maps to the plane: a z that is not 0 would be dropped.
        for (int i = 0; i < num_vertices; ++i) {
            if ((*result.initial)(i, 2) != 0.0)
                reader.fail_at(initial_header + 1 + i,
                               "initial position of vertex " + std::to_string(i) +
                                   " has z = " + io::format_number((*result.initial)(i, 2)) +
                                   ", but the rest shape is 2D (header on line " +
                                   std::to_string(initial_header) +
                                   "): a planar mesh maps to the plane");
        }
        result.initial = Eigen::MatrixXd(result.initial->leftCols(2));
    }

    int num_simplices = 0, k = 0;
    read_header(reader, "simplices", "#S k", num_simplices, k);
    if (k != 3 && k != 4) reader.fail(std::to_string(k) + " vertices per simplex; expected 3 or 4");
    const long long allocated = reader.fitting(num_simplices, k);
    mesh.simplices.resize(allocated, k);
    const std::string range = " out of range [0, " + std::to_string(num_vertices - 1) + "]";
    for (int s = 0; s < num_simplices; ++s) {
        if (!reader.next_line())
            reader.fail_file("file ends after " + std::to_string(s) + " of " +
                             std::to_string(num_simplices) + " simplices");
        const auto& tokens = reader.tokens();
        if (static_cast<int>(tokens.size()) != k)
            reader.fail("expected " + std::to_string(k) + " vertex indices for simplex " +
                        std::to_string(s) + ", found " + std::to_string(tokens.size()));
        reader.check_room(s, allocated, "simplices");
        for (int c = 0; c < k; ++c) {
            const long long v = reader.to_integer(tokens[c], "vertex index");
            if (v < 0 || v >= num_vertices) reader.fail("vertex " + std::to_string(v) + range);
            mesh.simplices(s, c) = static_cast<int>(v);
        }
    }

    // Optional handles: a count, then that many indices in any layout.
    std::string_view token;
    if (!reader.next_token(token)) return result;
    const int num_handles = reader.to_count(token, "handle count");
    const int count_line = reader.line_number();
    std::unordered_map<int, int> first_line;
    result.handles.reserve(reader.fitting(num_handles, 1));
    for (int h = 0; h < num_handles; ++h) {
        if (!reader.next_token(token))
            reader.fail_file("file ends after " + std::to_string(h) + " of " +
                             std::to_string(num_handles) + " handles (count on line " +
                             std::to_string(count_line) + ")");
        const long long v = reader.to_integer(token, "handle");
        if (v < 0 || v >= num_vertices) reader.fail("handle " + std::to_string(v) + range);
        const auto [it, inserted] = first_line.emplace(static_cast<int>(v), reader.line_number());
        if (!inserted)
            reader.fail("handle " + std::to_string(v) + " repeated (first on line " +
                        std::to_string(it->second) + ")");
        result.handles.push_back(static_cast<Index>(v));
    }
    if (reader.next_token(token))
        reader.fail("unexpected data " + io::quote(token) + " after the " +
                    std::to_string(num_handles) + " handles");
    return result;
}

Eigen::MatrixXd read_result_positions(const std::string& path) {
    io::TextReader reader(path);
    while (reader.next_line()) {
        const auto& header = reader.tokens();
        const std::string name(header[0]);
        if (header.size() < 2)
            reader.fail("expected a record header 'name dims...', found " +
                        io::quote(reader.line()));
        long long values = 1;
        std::vector<int> dims;
        for (std::size_t i = 1; i < header.size(); ++i) {
            dims.push_back(reader.to_count(header[i], "record dimension"));
            if (dims.back() > 0 && values > (1LL << 40) / dims.back())
                reader.fail("record " + io::quote(name) + " is too large");
            values *= dims.back();
        }
        const int header_line = reader.line_number();
        if (name != "resV") {
            // Skip the record's value line (absent when it has no values).
            if (values > 0 && !reader.next_line())
                reader.fail_file("file ends before the values of record " + io::quote(name) +
                                 " (line " + std::to_string(header_line) + ")");
            continue;
        }
        if (dims.size() != 2)
            reader.fail("record 'resV' has " + std::to_string(dims.size()) +
                        " dimensions; expected 'resV n d'");
        if (values == 0) return Eigen::MatrixXd(dims[0], dims[1]);
        if (!reader.next_line())
            reader.fail_file("file ends before the values of record 'resV' (line " +
                             std::to_string(header_line) + ")");
        const auto& tokens = reader.tokens();
        if (static_cast<long long>(tokens.size()) != values)
            reader.fail("expected " + std::to_string(values) + " values for 'resV " +
                        std::to_string(dims[0]) + " " + std::to_string(dims[1]) + "', found " +
                        std::to_string(tokens.size()));
        Eigen::MatrixXd positions(dims[0], dims[1]);  // its values are on the line just read
        for (int i = 0; i < dims[0]; ++i)
            for (int j = 0; j < dims[1]; ++j)
                positions(i, j) = reader.to_double(tokens[i * dims[1] + j], "value");
        return positions;
    }
    reader.fail_file("no 'resV n d' record");
}

void write_result_records(const std::string& path, const Eigen::MatrixXd& positions) {
    io::check_positions("write_result_records", positions, 1, static_cast<int>(1 << 30));
    AtomicFile file(path);
    std::ostream& out = file.stream();
    out << "resV " << positions.rows() << ' ' << positions.cols() << '\n';
    for (Eigen::Index i = 0; i < positions.rows(); ++i) {
        for (Eigen::Index j = 0; j < positions.cols(); ++j) {
            if (i > 0 || j > 0) out << ' ';
            out << positions(i, j);
        }
    }
    out << '\n';
    file.commit();
}

}  // namespace sa
