// read_vtk (vtk_io.h): legacy .vtk files, parsed here rather than by VTK's vtkDataSetReader.
// VTK 9.1's legacy readers trust the counts and keywords of the file: fuzzing found one crash
// after another in them (tests/fuzz/regressions/vtk), each guarded by a pre-scan that had to read
// the file as VTK would. Parsing the two dataset types we read ourselves removes the class:
// every count is checked against what the file can hold before anything is allocated, and every
// error names the file and the line (ASCII) or byte (BINARY).
//
// The format (VTK's "File Formats" document; versions 2 to 5.1):
//   # vtk DataFile Version x.y
//   title line
//   ASCII | BINARY
//   DATASET UNSTRUCTURED_GRID | POLYDATA
// then sections in any order until POINT_DATA or CELL_DATA (not read: the mesh is all we need):
//   FIELD name n, then per array `name components tuples type` and its values (or NULL_ARRAY)
//   POINTS n type, 3n values
//   CELLS n size (UNSTRUCTURED_GRID) or VERTICES, LINES, POLYGONS, TRIANGLE_STRIPS n size
//     (POLYDATA): before version 5, `size` integers, each cell its point count then its points;
//     from version 5 on, `OFFSETS type` with n offsets rising from 0 to `size`, then
//     `CONNECTIVITY type` with `size` point indices (the layout is told by the OFFSETS keyword)
//   CELL_TYPES n, n integers (UNSTRUCTURED_GRID)
//   METADATA, then lines up to a blank one
// Keywords are case-insensitive. BINARY data is big-endian and starts after the line of its
// section's header; the classic cell layout and CELL_TYPES are 4-byte integers there.
#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "geometry/io/byte_cursor.h"
#include "geometry/io/vtk_cells.h"
#include "geometry/io/vtk_io.h"
#include "optim/errors.h"

namespace sa {
namespace {

/// A value type of the format: its keyword and how a binary file holds it (bytes, floating,
/// signed).
struct ValueType {
    const char* name;
    io::BinaryType binary;
};

constexpr ValueType kValueTypes[] = {{"char", {1, false, true}},
                                     {"signed_char", {1, false, true}},
                                     {"unsigned_char", {1, false, false}},
                                     {"short", {2, false, true}},
                                     {"unsigned_short", {2, false, false}},
                                     {"int", {4, false, true}},
                                     {"unsigned_int", {4, false, false}},
                                     {"long", {8, false, true}},
                                     {"unsigned_long", {8, false, false}},
                                     {"vtktypeint64", {8, false, true}},
                                     {"vtktypeuint64", {8, false, false}},
                                     {"vtkidtype", {8, false, true}},
                                     {"float", {4, true, true}},
                                     {"double", {8, true, true}}};
constexpr const ValueType& kInt = kValueTypes[5];

/// Counts above this are refused before anything is allocated (a point or cell count must also
/// fit an int; this bounds the products of counts).
constexpr long long kMaxCount = 2147483647;

std::string upper(std::string_view token) {
    std::string text(token.substr(0, 40));
    for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

class LegacyVtkParser {
  public:
    explicit LegacyVtkParser(std::string path) : in_(std::move(path)) {}

    MeshFile read() {
        read_header();
        Eigen::MatrixXd points;
        bool have_points = false, have_cells = false, have_types = false;
        io::VtkCells cells;                         // UNSTRUCTURED_GRID
        std::array<io::VtkCells, 4> poly_sections;  // POLYDATA, in VTK's order of cell ids
        static const char* const kPolySections[] = {"vertices", "lines", "polygons",
                                                    "triangle_strips"};
        for (std::string_view token = in_.next_token(); !token.empty(); token = in_.next_token()) {
            const std::string section = upper(token);
            if (io::is_keyword(token, "point_data") || io::is_keyword(token, "cell_data")) break;
            if (io::is_keyword(token, "field")) {
                skip_field();
            } else if (io::is_keyword(token, "metadata")) {
                skip_metadata();
            } else if (io::is_keyword(token, "points")) {
                if (have_points) fail("a second POINTS section");
                points = read_points();
                have_points = true;
            } else if (!polydata_ && io::is_keyword(token, "cells")) {
                if (have_cells) fail("a second CELLS section");
                const std::vector<int> types = std::move(cells.types);
                cells = read_cells(section);
                cells.types = types;
                have_cells = true;
            } else if (!polydata_ && io::is_keyword(token, "cell_types")) {
                if (have_types) fail("a second CELL_TYPES section");
                cells.types = read_cell_types();
                have_types = true;
            } else {
                std::size_t kind = 0;
                while (kind < 4 && !(polydata_ && io::is_keyword(token, kPolySections[kind])))
                    ++kind;
                if (kind == 4)
                    fail("unknown section " + io::quoted_bytes(token) + " in a DATASET " +
                         (polydata_ ? "POLYDATA" : "UNSTRUCTURED_GRID"));
                if (poly_sections[kind].offsets.size() > 1)
                    fail("a second " + section + " section");
                poly_sections[kind] = read_cells(section);
                set_poly_types(kind, poly_sections[kind]);
            }
        }
        if (!have_points) throw InputError(in_.path() + ": no POINTS section");
        if (polydata_) {
            cells = io::VtkCells{};
            for (const io::VtkCells& section : poly_sections) append(cells, section);
        } else if (have_cells != have_types) {
            throw InputError(in_.path() + (have_cells ? ": a CELLS section without CELL_TYPES"
                                                      : ": a CELL_TYPES section without CELLS"));
        } else if (cells.types.size() + 1 != cells.offsets.size()) {
            throw InputError(in_.path() + ": CELLS declares " +
                             std::to_string(cells.offsets.size() - 1) + " cells but CELL_TYPES " +
                             std::to_string(cells.types.size()));
        }
        return io::mesh_from_vtk_cells(in_.path(), points, cells);
    }

  private:
    void read_header() {
        const std::string_view bytes = in_.bytes();
        if (bytes.substr(0, 3) == "\xEF\xBB\xBF")
            fail("starts with a UTF-8 byte-order mark, which legacy VTK readers do not accept");
        const std::string_view first = in_.rest_of_line();
        if (const std::size_t bad = io::first_control_byte(first); bad != std::string_view::npos)
            throw InputError(in_.path() + ": " + io::control_byte_message(first, bad) +
                             ", so not a legacy VTK file: a binary or compressed file?");
        if (first.rfind("# vtk DataFile Version", 0) != 0)
            fail("expected '# vtk DataFile Version x.y', found " + io::quoted_bytes(first));
        in_.skip_line();  // the version line
        in_.skip_line();  // the title
        const std::string_view format = in_.token("ASCII or BINARY");
        if (io::is_keyword(format, "binary")) {
            in_.set_binary();
        } else if (io::is_keyword(format, "ascii")) {
            const std::size_t bad = io::first_control_byte(bytes.substr(in_.position()));
            if (bad != std::string_view::npos) {
                const std::size_t at = in_.position() + bad;
                while (in_.position() + in_.rest_of_line().size() < at)
                    in_.skip_line();  // to the line of the bad byte, for the message
                fail(io::control_byte_message(bytes, at) + " in an ASCII file");
            }
        } else {
            fail("expected ASCII or BINARY, found " + io::quoted_bytes(format));
        }
        const std::string_view dataset = in_.token("DATASET");
        if (!io::is_keyword(dataset, "dataset"))
            fail("expected DATASET, found " + io::quoted_bytes(dataset));
        const std::string_view type = in_.token("the dataset type");
        if (io::is_keyword(type, "polydata")) {
            polydata_ = true;
        } else if (!io::is_keyword(type, "unstructured_grid")) {
            const bool known = io::is_keyword(type, "structured_points") ||
                               io::is_keyword(type, "structured_grid") ||
                               io::is_keyword(type, "rectilinear_grid");
            fail((known ? "dataset type " : "unknown dataset type ") + io::quoted_bytes(type) +
                 "; only UNSTRUCTURED_GRID and POLYDATA are supported");
        }
    }

    Eigen::MatrixXd read_points() {
        const long long n = count("POINTS", "point count");
        const ValueType& type = value_type("POINTS");
        const std::vector<double> values = read_numbers<double>(3 * n, type, "POINTS");
        Eigen::MatrixXd points(n, 3);
        for (long long i = 0; i < n; ++i) {
            for (int j = 0; j < 3; ++j) points(i, j) = values[static_cast<std::size_t>(3 * i + j)];
        }
        return points;
    }

    /// A cell section after its keyword, in either layout; the types are left empty.
    io::VtkCells read_cells(const std::string& section) {
        const long long n = count(section, "cell count");
        const long long size = count(section, "size");
        if (in_.binary()) in_.skip_line();
        io::VtkCells cells;
        if (next_is_offsets()) {
            // Version 5: n offsets rising from 0 to size (n = #cells + 1), then the points.
            in_.token("OFFSETS");
            const std::string offsets_section = section + " OFFSETS";
            cells.offsets =
                read_numbers<std::int64_t>(n, integer_type(offsets_section), offsets_section);
            if (cells.offsets.empty()) cells.offsets.push_back(0);
            for (std::size_t c = 0; c < cells.offsets.size(); ++c) {
                const std::int64_t before = c == 0 ? 0 : cells.offsets[c - 1];
                if (cells.offsets[c] < before || cells.offsets[c] > size ||
                    (c == 0 && cells.offsets[c] != 0) ||
                    (c + 1 == cells.offsets.size() && cells.offsets[c] != size))
                    fail(offsets_section + ": offset " + std::to_string(c) + " is " +
                         std::to_string(cells.offsets[c]) + "; they must rise from 0 to " +
                         std::to_string(size));
            }
            const std::string_view keyword = in_.token("CONNECTIVITY");
            if (!io::is_keyword(keyword, "connectivity"))
                fail(section + ": expected CONNECTIVITY after the offsets, found " +
                     io::quoted_bytes(keyword));
            const std::string connectivity_section = section + " CONNECTIVITY";
            cells.connectivity = read_numbers<std::int64_t>(
                size, integer_type(connectivity_section), connectivity_section);
            return cells;
        }
        // Classic: `size` integers, each cell its point count then its points.
        const std::vector<std::int64_t> data = read_numbers<std::int64_t>(size, kInt, section);
        cells.connectivity.reserve(data.size());
        std::size_t k = 0;
        for (long long c = 0; c < n; ++c) {
            const std::int64_t points = k < data.size() ? data[k] : -1;
            if (points < 0 || static_cast<std::uint64_t>(points) >= data.size() - k)
                fail(section + ": " + std::to_string(size) + " numbers do not hold " +
                     std::to_string(n) + " cells of 'COUNT POINTS...' (cell " + std::to_string(c) +
                     ")");
            const auto first = data.begin() + static_cast<std::ptrdiff_t>(k) + 1;
            cells.connectivity.insert(cells.connectivity.end(), first,
                                      first + static_cast<std::ptrdiff_t>(points));
            cells.offsets.push_back(static_cast<std::int64_t>(cells.connectivity.size()));
            k += static_cast<std::size_t>(points) + 1;
        }
        if (k != data.size())
            fail(section + ": " + std::to_string(size) + " numbers hold more than " +
                 std::to_string(n) + " cells");
        return cells;
    }

    std::vector<int> read_cell_types() {
        const long long n = count("CELL_TYPES", "count");
        const std::vector<std::int64_t> values = read_numbers<std::int64_t>(n, kInt, "CELL_TYPES");
        return std::vector<int>(values.begin(), values.end());  // 4-byte values
    }

    /// POLYDATA cells take their type from their section and point count, as vtkPolyData does.
    static void set_poly_types(std::size_t kind, io::VtkCells& cells) {
        const std::size_t n = cells.offsets.size() - 1;
        cells.types.resize(n);
        for (std::size_t c = 0; c < n; ++c) {
            const std::int64_t points = cells.offsets[c + 1] - cells.offsets[c];
            switch (kind) {
                case 0:
                    cells.types[c] = points == 1 ? 1 : 2;
                    break;  // vertex, poly vertex
                case 1:
                    cells.types[c] = points == 2 ? 3 : 4;
                    break;  // line, poly line
                case 2:     // triangle, quad, polygon
                    cells.types[c] = points == 3 ? io::kVtkTriangle : points == 4 ? 9 : 7;
                    break;
                default:
                    cells.types[c] = 6;
                    break;  // triangle strip
            }
        }
    }

    static void append(io::VtkCells& to, const io::VtkCells& from) {
        const std::int64_t shift = to.offsets.back();
        to.types.insert(to.types.end(), from.types.begin(), from.types.end());
        for (std::size_t c = 1; c < from.offsets.size(); ++c)
            to.offsets.push_back(from.offsets[c] + shift);
        to.connectivity.insert(to.connectivity.end(), from.connectivity.begin(),
                               from.connectivity.end());
    }

    /// FIELD NAME COUNT, then per array NAME COMPONENTS TUPLES TYPE and its values (or
    /// NULL_ARRAY), each optionally followed by METADATA: read and dropped.
    void skip_field() {
        in_.token("the FIELD's name");
        const long long arrays = count("FIELD", "array count");
        for (long long a = 0; a < arrays; ++a) {
            const std::string_view name = in_.token("a FIELD array");
            if (io::is_keyword(name, "null_array")) continue;
            const std::string section = "FIELD array " + io::quoted_bytes(name);
            const long long components = count(section, "component count");
            const long long tuples = count(section, "tuple count");
            const ValueType& type = value_type(section);
            read_numbers<double>(components * tuples, type, section);
            if (io::is_keyword(in_.peek_token(), "metadata")) {
                in_.next_token();
                skip_metadata();
            }
        }
    }

    /// METADATA's lines, up to a blank line (or the end of the file).
    void skip_metadata() {
        in_.skip_line();
        while (in_.remaining() > 0) {
            const std::string_view line = in_.rest_of_line();
            in_.skip_line();
            if (line.find_first_not_of(" \t\r\f\v") == std::string_view::npos) break;
        }
    }

    /// `n` numbers of `type` (ASCII tokens, or BINARY big-endian values after the section's
    /// header line), as T.
    template <class T>
    std::vector<T> read_numbers(long long n, const ValueType& type, const std::string& section) {
        // In a BINARY file the values start on the line after the section's header.
        if (in_.binary() && in_.position() > 0 && in_.bytes()[in_.position() - 1] != '\n')
            in_.skip_line();
        // Refused before allocating: a count the rest of the file cannot hold (an ASCII number
        // takes a character and a separator).
        const std::size_t left = in_.remaining();
        const std::size_t room =
            in_.binary() ? left / static_cast<std::size_t>(type.binary.bytes) : left / 2 + 1;
        if (n < 0 || static_cast<unsigned long long>(n) > room)
            fail(section + " is cut short (" + std::to_string(n) + " numbers declared, " +
                 std::to_string(left) + " bytes left in the file)");
        std::vector<T> values(static_cast<std::size_t>(n));
        for (long long i = 0; i < n; ++i) {
            T& value = values[static_cast<std::size_t>(i)];
            if (in_.binary()) {
                if constexpr (std::is_floating_point_v<T>)
                    value = in_.binary_double(type.binary, true);
                else
                    value = in_.binary_integer(type.binary, true, section);
                continue;
            }
            const std::string_view text = in_.next_token();
            if (text.empty())
                fail(section + " is cut short: the file ends after " + std::to_string(i) + " of " +
                     std::to_string(n) + " numbers");
            if constexpr (std::is_floating_point_v<T>)
                value = in_.to_double(text, section);
            else
                value = in_.to_integer(text, section);
        }
        return values;
    }

    /// A count after a section's keyword: a whole number in [0, kMaxCount].
    long long count(const std::string& section, const char* what) {
        const std::string_view text = in_.token(section + "'s " + what);
        const std::string expected = section + ": expected its " + what +
                                     " (a whole number from 0 to " + std::to_string(kMaxCount) +
                                     "), found " + io::quoted_bytes(text);
        long long value = -1;
        try {
            value = in_.to_integer(text, section);
        } catch (const InputError&) {
            fail(expected);
        }
        if (value < 0 || value > kMaxCount) fail(expected);
        return value;
    }

    const ValueType& value_type(const std::string& section) {
        const std::string_view text = in_.token(section + "'s value type");
        for (const ValueType& type : kValueTypes) {
            if (io::is_keyword(text, type.name)) return type;
        }
        fail(section + ": value type " + io::quoted_bytes(text) +
             " is not read (numeric types only: char ... double, vtktypeint64, vtkidtype)");
    }

    const ValueType& integer_type(const std::string& section) {
        const ValueType& type = value_type(section);
        if (type.binary.floating)
            fail(section + ": value type " + type.name + " where integers belong");
        return type;
    }

    /// Whether the cell section's version-5 OFFSETS keyword comes next (in a BINARY file, at the
    /// start of the line after the section's header).
    bool next_is_offsets() {
        if (!in_.binary()) return io::is_keyword(in_.peek_token(), "offsets");
        const std::string_view rest = in_.bytes().substr(in_.position());
        return rest.size() > 7 && io::is_keyword(rest.substr(0, 7), "offsets") &&
               (rest[7] == ' ' || rest[7] == '\t');
    }

    [[noreturn]] void fail(const std::string& what) const { in_.fail(what); }

    io::ByteCursor in_;
    bool polydata_ = false;
};

}  // namespace

MeshFile read_vtk(const std::string& path) {
    return LegacyVtkParser(path).read();
}

}  // namespace sa
