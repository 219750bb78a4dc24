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
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/io/text_reader.h"
#include "geometry/io/vtk_cells.h"
#include "geometry/io/vtk_io.h"
#include "optim/errors.h"

namespace sa {
namespace {

/// A value type of the format: its keyword and its size in a binary file.
struct ValueType {
    const char* name;
    int bytes;
    bool floating;
    bool is_signed;
};

constexpr ValueType kValueTypes[] = {{"char", 1, false, true},
                                     {"signed_char", 1, false, true},
                                     {"unsigned_char", 1, false, false},
                                     {"short", 2, false, true},
                                     {"unsigned_short", 2, false, false},
                                     {"int", 4, false, true},
                                     {"unsigned_int", 4, false, false},
                                     {"long", 8, false, true},
                                     {"unsigned_long", 8, false, false},
                                     {"vtktypeint64", 8, false, true},
                                     {"vtktypeuint64", 8, false, false},
                                     {"vtkidtype", 8, false, true},
                                     {"float", 4, true, true},
                                     {"double", 8, true, true}};
constexpr const ValueType& kInt = kValueTypes[5];

/// Counts above this are refused before anything is allocated (a point or cell count must also
/// fit an int; this bounds the products of counts).
constexpr long long kMaxCount = std::numeric_limits<int>::max();

bool is_space(char c) {
    return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\f' || c == '\v';
}

bool is_keyword(std::string_view token, std::string_view keyword) {
    if (token.size() != keyword.size()) return false;
    for (std::size_t i = 0; i < token.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(token[i])) != keyword[i]) return false;
    }
    return true;
}

/// The offset of the first byte that is neither printable nor whitespace, or npos.
std::size_t first_control_byte(std::string_view bytes) {
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const auto c = static_cast<unsigned char>(bytes[i]);
        if ((c < 0x20 && !is_space(static_cast<char>(c))) || c == 0x7f) return i;
    }
    return std::string_view::npos;
}

std::string control_byte_message(std::string_view bytes, std::size_t offset) {
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02x", static_cast<unsigned char>(bytes[offset]));
    return std::string("not a text file (byte ") + byte + " at offset " + std::to_string(offset) +
           ")";
}

/// `'token'` for messages: at most 40 bytes, bytes that are not printable as \xNN (a BINARY
/// file's data read as a keyword).
std::string quoted(std::string_view token) {
    std::string text = "'";
    for (const char c : token.substr(0, 40)) {
        if (std::isprint(static_cast<unsigned char>(c)) != 0) {
            text.push_back(c);
        } else {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\x%02x", static_cast<unsigned char>(c));
            text.append(escape);
        }
    }
    return text + (token.size() > 40 ? "...'" : "'");
}

class LegacyVtkParser {
  public:
    explicit LegacyVtkParser(std::string path) : path_(std::move(path)) {
        io::check_readable(path_);
        std::ifstream in(path_, std::ios::binary);
        std::ostringstream buffer;
        buffer << in.rdbuf();
        if (in.bad()) throw InputError(path_ + ": cannot read (" + std::strerror(errno) + ")");
        bytes_ = std::move(buffer).str();
    }

    MeshFile read() {
        read_header();
        Eigen::MatrixXd points;
        bool have_points = false, have_cells = false, have_types = false;
        io::VtkCells cells;                         // UNSTRUCTURED_GRID
        std::array<io::VtkCells, 4> poly_sections;  // POLYDATA, in VTK's order of cell ids
        static const char* const kPolySections[] = {"vertices", "lines", "polygons",
                                                    "triangle_strips"};
        for (std::string_view token = next_token(); !token.empty(); token = next_token()) {
            const std::string section = upper(token);
            if (is_keyword(token, "point_data") || is_keyword(token, "cell_data")) break;
            if (is_keyword(token, "field")) {
                skip_field();
            } else if (is_keyword(token, "metadata")) {
                skip_metadata();
            } else if (is_keyword(token, "points")) {
                if (have_points) fail("a second POINTS section");
                points = read_points();
                have_points = true;
            } else if (!polydata_ && is_keyword(token, "cells")) {
                if (have_cells) fail("a second CELLS section");
                const std::vector<int> types = std::move(cells.types);
                cells = read_cells(section);
                cells.types = types;
                have_cells = true;
            } else if (!polydata_ && is_keyword(token, "cell_types")) {
                if (have_types) fail("a second CELL_TYPES section");
                cells.types = read_cell_types();
                have_types = true;
            } else {
                std::size_t kind = 0;
                while (kind < 4 && !(polydata_ && is_keyword(token, kPolySections[kind]))) ++kind;
                if (kind == 4)
                    fail("unknown section " + quoted(token) + " in a DATASET " +
                         (polydata_ ? "POLYDATA" : "UNSTRUCTURED_GRID"));
                if (poly_sections[kind].offsets.size() > 1)
                    fail("a second " + section + " section");
                poly_sections[kind] = read_cells(section);
                set_poly_types(kind, poly_sections[kind]);
            }
        }
        if (!have_points) throw InputError(path_ + ": no POINTS section");
        if (polydata_) {
            cells = io::VtkCells{};
            for (const io::VtkCells& section : poly_sections) append(cells, section);
        } else if (have_cells != have_types) {
            throw InputError(path_ + (have_cells ? ": a CELLS section without CELL_TYPES"
                                                 : ": a CELL_TYPES section without CELLS"));
        } else if (cells.types.size() + 1 != cells.offsets.size()) {
            throw InputError(path_ + ": CELLS declares " +
                             std::to_string(cells.offsets.size() - 1) + " cells but CELL_TYPES " +
                             std::to_string(cells.types.size()));
        }
        return io::mesh_from_vtk_cells(path_, points, cells);
    }

  private:
    void read_header() {
        if (bytes_.compare(0, 3, "\xEF\xBB\xBF") == 0)
            fail("starts with a UTF-8 byte-order mark, which legacy VTK readers do not accept");
        const std::string_view first = line_at(0);
        if (const std::size_t bad = first_control_byte(first); bad != std::string_view::npos)
            throw InputError(path_ + ": " + control_byte_message(first, bad) +
                             ", so not a legacy VTK file: a binary or compressed file?");
        if (first.rfind("# vtk DataFile Version", 0) != 0)
            fail("expected '# vtk DataFile Version x.y', found " + quoted(first));
        skip_rest_of_line();  // the version line
        skip_rest_of_line();  // the title
        const std::string_view format = token("ASCII or BINARY");
        if (is_keyword(format, "binary")) {
            binary_ = true;
        } else if (is_keyword(format, "ascii")) {
            const std::string_view rest = std::string_view(bytes_).substr(position_);
            if (const std::size_t bad = first_control_byte(rest); bad != std::string_view::npos) {
                position_ += bad;
                line_ += static_cast<int>(std::count(rest.begin(), rest.begin() + bad, '\n'));
                fail(control_byte_message(bytes_, position_) + " in an ASCII file");
            }
        } else {
            fail("expected ASCII or BINARY, found " + quoted(format));
        }
        const std::string_view dataset = token("DATASET");
        if (!is_keyword(dataset, "dataset")) fail("expected DATASET, found " + quoted(dataset));
        const std::string_view type = token("the dataset type");
        if (is_keyword(type, "polydata")) {
            polydata_ = true;
        } else if (!is_keyword(type, "unstructured_grid")) {
            const bool known = is_keyword(type, "structured_points") ||
                               is_keyword(type, "structured_grid") ||
                               is_keyword(type, "rectilinear_grid");
            fail((known ? "dataset type " : "unknown dataset type ") + quoted(type) +
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
        if (binary_) skip_rest_of_line();
        io::VtkCells cells;
        if (next_is_offsets()) {
            // Version 5: n offsets rising from 0 to size (n = #cells + 1), then the points.
            token("OFFSETS");
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
            const std::string_view keyword = token("CONNECTIVITY");
            if (!is_keyword(keyword, "connectivity"))
                fail(section + ": expected CONNECTIVITY after the offsets, found " +
                     quoted(keyword));
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
        token("the FIELD's name");
        const long long arrays = count("FIELD", "array count");
        for (long long a = 0; a < arrays; ++a) {
            const std::string_view name = token("a FIELD array");
            if (is_keyword(name, "null_array")) continue;
            const std::string section = "FIELD array " + quoted(name);
            const long long components = count(section, "component count");
            const long long tuples = count(section, "tuple count");
            const ValueType& type = value_type(section);
            read_numbers<double>(components * tuples, type, section);
            if (is_keyword(peek_token(), "metadata")) {
                next_token();
                skip_metadata();
            }
        }
    }

    /// METADATA's lines, up to a blank line (or the end of the file).
    void skip_metadata() {
        skip_rest_of_line();
        while (position_ < bytes_.size()) {
            const std::string_view line = line_at(position_);
            skip_rest_of_line();
            if (line.find_first_not_of(" \t\r\f\v") == std::string_view::npos) break;
        }
    }

    /// `n` numbers of `type` (ASCII tokens, or BINARY big-endian values after the section's
    /// header line), as T.
    template <class T>
    std::vector<T> read_numbers(long long n, const ValueType& type, const std::string& section) {
        // Refused before allocating: a count the rest of the file cannot hold (an ASCII number
        // takes a character and a separator).
        const std::size_t left = bytes_.size() - position_;
        if (n < 0 || static_cast<unsigned long long>(n) >
                         (binary_ ? left / static_cast<std::size_t>(type.bytes) : left / 2 + 1))
            fail(section + " is cut short (" + std::to_string(n) + " numbers declared, " +
                 std::to_string(left) + " bytes left in the file)");
        std::vector<T> values(static_cast<std::size_t>(n));
        if (binary_) {
            skip_rest_of_line_if_at_header();
            if (static_cast<unsigned long long>(n) >
                (bytes_.size() - position_) / static_cast<std::size_t>(type.bytes))
                fail(section + " is cut short (" + std::to_string(n) + " numbers declared)");
            for (T& value : values) value = binary_value<T>(type, section);
            return values;
        }
        for (long long i = 0; i < n; ++i) {
            const std::string_view text = next_token();
            if (text.empty())
                fail(section + " is cut short: the file ends after " + std::to_string(i) + " of " +
                     std::to_string(n) + " numbers");
            values[static_cast<std::size_t>(i)] = ascii_value<T>(text, type, section);
        }
        return values;
    }

    template <class T>
    T ascii_value(std::string_view text, const ValueType& type, const std::string& section) {
        const char* end = text.data() + text.size();
        if (type.floating || std::is_floating_point_v<T>) {
            double value = 0;
            const auto [stop, error] = std::from_chars(text.data(), end, value);
            if (error != std::errc() || stop != end)
                fail(section + " holds " + quoted(text) + " where a number belongs");
            if constexpr (std::is_floating_point_v<T>) {
                return value;
            } else {
                fail(section + " holds " + quoted(text) + " where a whole number belongs");
            }
        } else {
            long long value = 0;
            const char* begin = text.data() + (text[0] == '+' ? 1 : 0);
            const auto [stop, error] = std::from_chars(begin, end, value);
            if (error != std::errc() || stop != end)
                fail(section + " holds " + quoted(text) + " where a whole number belongs");
            return static_cast<T>(value);
        }
    }

    template <class T>
    T binary_value(const ValueType& type, const std::string& section) {
        std::uint64_t bits = 0;
        for (int b = 0; b < type.bytes; ++b)
            bits = bits << 8 | static_cast<unsigned char>(bytes_[position_++]);
        if (type.floating) {
            double value;
            if (type.bytes == 4) {
                float f;
                const auto narrow = static_cast<std::uint32_t>(bits);
                std::memcpy(&f, &narrow, 4);
                value = f;
            } else {
                std::memcpy(&value, &bits, 8);
            }
            if constexpr (std::is_floating_point_v<T>) return value;
            fail(section + " holds floating-point values where whole numbers belong");
        }
        const int shift = 64 - 8 * type.bytes;
        std::int64_t value;
        if (type.is_signed) {
            value = static_cast<std::int64_t>(bits << shift) >> shift;  // sign-extended
        } else {
            if (bits > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
                fail(section + " holds a value out of range");
            value = static_cast<std::int64_t>(bits);
        }
        return static_cast<T>(value);
    }

    /// A count after a section's keyword: a whole number in [0, kMaxCount].
    long long count(const std::string& section, const char* what) {
        const std::string_view text = token(section + "'s " + what);
        long long value = -1;
        const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || stop != text.data() + text.size() || value < 0 ||
            value > kMaxCount)
            fail(section + ": expected its " + what + " (a whole number from 0 to " +
                 std::to_string(kMaxCount) + "), found " + quoted(text));
        return value;
    }

    const ValueType& value_type(const std::string& section) {
        const std::string_view text = token(section + "'s value type");
        for (const ValueType& type : kValueTypes) {
            if (is_keyword(text, type.name)) return type;
        }
        fail(section + ": value type " + quoted(text) +
             " is not read (numeric types only: char ... double, vtktypeint64, vtkidtype)");
    }

    const ValueType& integer_type(const std::string& section) {
        const ValueType& type = value_type(section);
        if (type.floating) fail(section + ": value type " + type.name + " where integers belong");
        return type;
    }

    /// Whether the cell section's version-5 OFFSETS keyword comes next (in a BINARY file, at the
    /// start of the line after the section's header).
    bool next_is_offsets() {
        if (!binary_) return is_keyword(peek_token(), "offsets");
        const std::string_view rest = std::string_view(bytes_).substr(position_);
        return rest.size() > 7 && is_keyword(rest.substr(0, 7), "offsets") && is_space(rest[7]);
    }

    /// In a BINARY file, a section's values start on the line after its header: skips what is
    /// left of the header's line unless already at a line start.
    void skip_rest_of_line_if_at_header() {
        if (position_ > 0 && bytes_[position_ - 1] != '\n') skip_rest_of_line();
    }

    /// The next token (a run of non-whitespace bytes), "" at the end of the file (the line then
    /// stays the last one with a token, for messages).
    std::string_view next_token() {
        const int line = line_;
        while (position_ < bytes_.size() && is_space(bytes_[position_])) {
            if (bytes_[position_] == '\n') ++line_;
            ++position_;
        }
        if (position_ == bytes_.size()) line_ = line;
        const std::size_t begin = position_;
        while (position_ < bytes_.size() && !is_space(bytes_[position_])) ++position_;
        return std::string_view(bytes_).substr(begin, position_ - begin);
    }

    std::string_view peek_token() {
        const std::size_t position = position_;
        const int line = line_;
        const std::string_view token = next_token();
        position_ = position;
        line_ = line;
        return token;
    }

    /// The next token; fails when the file ends where `what` belongs.
    std::string_view token(const std::string& what) {
        const std::string_view token = next_token();
        if (token.empty()) fail("the file ends where " + what + " belongs");
        return token;
    }

    std::string_view line_at(std::size_t position) const {
        const std::size_t end = std::min(bytes_.find('\n', position), bytes_.size());
        return std::string_view(bytes_).substr(position, end - position);
    }

    void skip_rest_of_line() {
        const std::size_t end = bytes_.find('\n', position_);
        position_ = end == std::string::npos ? bytes_.size() : end + 1;
        if (end != std::string::npos) ++line_;
    }

    static std::string upper(std::string_view token) {
        std::string text(token.substr(0, 40));
        for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        return text;
    }

    /// Throws `PATH:LINE: what` (ASCII, or a BINARY file's header) or `PATH: byte N: what`.
    [[noreturn]] void fail(const std::string& what) const {
        if (binary_) throw InputError(path_ + ": byte " + std::to_string(position_) + ": " + what);
        throw InputError(path_ + ":" + std::to_string(line_) + ": " + what);
    }

    std::string path_;
    std::string bytes_;
    std::size_t position_ = 0;
    int line_ = 1;
    bool binary_ = false;
    bool polydata_ = false;
};

}  // namespace

MeshFile read_vtk(const std::string& path) {
    return LegacyVtkParser(path).read();
}

}  // namespace sa
