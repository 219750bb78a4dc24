#include "geometry/io/vtk_io_plugin.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellTypes.h>
#include <vtkDataObjectTypes.h>
#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/io/atomic_file.h"
#include "geometry/io/text_reader.h"
#include "geometry/io/vtk_capture.h"
#include "geometry/io/write_checks.h"
#include "optim/errors.h"

namespace sa {
namespace {

std::string cell_type_name(int type) {
    const char* name = vtkCellTypes::GetClassNameFromTypeId(type);
    return std::to_string(type) + " (" + (name != nullptr ? name : "unknown") + ")";
}

MeshFile to_mesh_file(const std::string& path, vtkDataSet* data) {
    MeshFile result;
    auto& mesh = result.mesh;
    const vtkIdType num_points = data->GetNumberOfPoints();
    const vtkIdType num_cells = data->GetNumberOfCells();
    if (num_points > std::numeric_limits<int>::max() || num_cells > std::numeric_limits<int>::max())
        throw InputError(path + ": too many points or cells");

    int type = 0;
    for (vtkIdType c = 0; c < num_cells; ++c) {
        const int t = data->GetCellType(c);
        if (c == 0) {
            if (t != VTK_TRIANGLE && t != VTK_TETRA)
                throw InputError(path + ": cell 0 has type " + cell_type_name(t) +
                                 "; only triangles (5) or tetrahedra (10) are supported");
            type = t;
        } else if (t != type) {
            throw InputError(path + ": cell " + std::to_string(c) + " has type " +
                             cell_type_name(t) + " but cell 0 has type " + cell_type_name(type) +
                             "; all cells must be triangles (5) or all tetrahedra (10)");
        }
    }
    const int k = type == VTK_TETRA ? 4 : 3;

    bool flat = type == VTK_TRIANGLE;
    Eigen::MatrixXd points(num_points, 3);
    for (vtkIdType i = 0; i < num_points; ++i) {
        double p[3];
        data->GetPoint(i, p);
        for (int j = 0; j < 3; ++j) {
            if (!std::isfinite(p[j]))
                throw InputError(path + ": point " + std::to_string(i) +
                                 " has a non-finite coordinate");
            points(i, j) = p[j];
        }
        if (p[2] != 0.0) flat = false;
    }
    mesh.vertices = flat ? Eigen::MatrixXd(points.leftCols(2)) : points;

    mesh.simplices.resize(num_cells, k);
    auto ids = vtkSmartPointer<vtkIdList>::New();
    for (vtkIdType c = 0; c < num_cells; ++c) {
        data->GetCellPoints(c, ids);
        if (ids->GetNumberOfIds() != k)
            throw InputError(path + ": cell " + std::to_string(c) + " has " +
                             std::to_string(ids->GetNumberOfIds()) + " points; expected " +
                             std::to_string(k));
        for (int j = 0; j < k; ++j) {
            const vtkIdType v = ids->GetId(j);
            if (v < 0 || v >= num_points)
                throw InputError(path + ": cell " + std::to_string(c) + " refers to point " +
                                 std::to_string(v) + ", out of range [0, " +
                                 std::to_string(num_points - 1) + "]");
            mesh.simplices(c, j) = static_cast<int>(v);
        }
    }
    return result;
}

// Checks a writer's arguments; throws InvalidArgumentError naming `function`.
void check_arguments(const char* function, const Eigen::MatrixXd& positions,
                     const Eigen::MatrixXi& simplices, const std::vector<DataArray>& point_data,
                     const std::vector<DataArray>& cell_data) {
    io::check_positions(function, positions);
    io::check_simplices(function, "simplices", simplices, positions.rows());
    if (simplices.cols() == 4 && positions.cols() != 3)
        throw InvalidArgumentError(std::string(function) + ": tetrahedra need 3D positions");
    auto check_arrays = [&](const std::vector<DataArray>& arrays, const char* kind,
                            Eigen::Index rows) {
        std::set<std::string> names;
        for (const DataArray& array : arrays) {
            const std::string where =
                std::string(function) + ": " + kind + " array '" + array.name + "'";
            if (array.name.empty())
                throw InvalidArgumentError(std::string(function) + ": " + kind +
                                           " array with an empty name");
            if (!names.insert(array.name).second)
                throw InvalidArgumentError(where + " given twice");
            if (array.values.rows() != rows || array.values.cols() < 1)
                throw InvalidArgumentError(where + " is " + std::to_string(array.values.rows()) +
                                           " x " + std::to_string(array.values.cols()) +
                                           "; expected " + std::to_string(rows) +
                                           " rows and at least one column");
            for (Eigen::Index i = 0; i < array.values.rows(); ++i) {
                for (Eigen::Index j = 0; j < array.values.cols(); ++j) {
                    const double value = array.values(i, j);
                    const bool bad = array.integer
                                         ? !(value == std::floor(value) &&
                                             std::abs(value) <= std::numeric_limits<int>::max())
                                         : !std::isfinite(value);
                    if (bad) {
                        std::ostringstream message;
                        message << where << " row " << i << " column " << j << " is " << value
                                << (array.integer ? ", not an int" : ", not finite");
                        throw InvalidArgumentError(message.str());
                    }
                }
            }
        }
    };
    check_arrays(point_data, "point data", positions.rows());
    check_arrays(cell_data, "cell data", simplices.rows());
}

// The grid to write (the arguments are checked).
vtkSmartPointer<vtkUnstructuredGrid> make_grid(const Eigen::MatrixXd& positions,
                                               const Eigen::MatrixXi& simplices,
                                               const std::vector<DataArray>& point_data,
                                               const std::vector<DataArray>& cell_data) {
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(positions.rows());
    for (Eigen::Index i = 0; i < positions.rows(); ++i)
        points->SetPoint(i, positions(i, 0), positions(i, 1),
                         positions.cols() == 3 ? positions(i, 2) : 0.0);
    grid->SetPoints(points);
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->AllocateExact(simplices.rows(), simplices.size());
    vtkIdType ids[4];
    for (Eigen::Index e = 0; e < simplices.rows(); ++e) {
        for (Eigen::Index c = 0; c < simplices.cols(); ++c) ids[c] = simplices(e, c);
        cells->InsertNextCell(simplices.cols(), ids);
    }
    grid->SetCells(simplices.cols() == 4 ? VTK_TETRA : VTK_TRIANGLE, cells);

    auto add_arrays = [](const std::vector<DataArray>& arrays, vtkDataSetAttributes* target) {
        for (const DataArray& array : arrays) {
            vtkSmartPointer<vtkDataArray> data;
            if (array.integer)
                data = vtkSmartPointer<vtkIntArray>::New();
            else
                data = vtkSmartPointer<vtkDoubleArray>::New();
            data->SetName(array.name.c_str());
            data->SetNumberOfComponents(static_cast<int>(array.values.cols()));
            data->SetNumberOfTuples(array.values.rows());
            for (Eigen::Index i = 0; i < array.values.rows(); ++i)
                for (Eigen::Index j = 0; j < array.values.cols(); ++j)
                    data->SetComponent(i, static_cast<int>(j), array.values(i, j));
            target->AddArray(data);
        }
    };
    add_arrays(point_data, grid->GetPointData());
    add_arrays(cell_data, grid->GetCellData());
    return grid;
}

// An array name for the legacy format: VTK's readers decode `%XX`, and names cannot hold spaces.
std::string encode_name(const std::string& name) {
    static const char* kHex = "0123456789ABCDEF";
    std::string encoded;
    for (const char c : name) {
        const auto u = static_cast<unsigned char>(c);
        if (std::isgraph(u) != 0 && c != '%' && c != '"') {
            encoded.push_back(c);
        } else {
            encoded.push_back('%');
            encoded.push_back(kHex[u >> 4]);
            encoded.push_back(kHex[u & 15]);
        }
    }
    return encoded;
}

void write_legacy_arrays(std::ostream& out, const char* section, Eigen::Index rows,
                         const std::vector<DataArray>& arrays) {
    if (arrays.empty()) return;
    out << section << ' ' << rows << "\nFIELD FieldData " << arrays.size() << '\n';
    for (const DataArray& array : arrays) {
        out << encode_name(array.name) << ' ' << array.values.cols() << ' ' << rows << ' '
            << (array.integer ? "int" : "double") << '\n';
        for (Eigen::Index i = 0; i < rows; ++i) {
            for (Eigen::Index j = 0; j < array.values.cols(); ++j) {
                if (j > 0) out << ' ';
                if (array.integer)
                    out << static_cast<int>(array.values(i, j));
                else
                    out << array.values(i, j);
            }
            out << '\n';
        }
    }
}

/// Runs `reader` on `path` with VTK's messages captured; throws InputError `PATH: cannot read as
/// FORMAT (VTK: ...)` when VTK reported an error.
template <class Reader>
void run_reader(Reader& reader, const std::string& path, const std::string& format) {
    io::check_readable(path);
    reader.SetFileName(path.c_str());
    std::string error;
    {
        VtkCapture capture;
        reader.Update();
        error = capture.error();
    }
    if (!error.empty())
        throw InputError(path + ": cannot read as " + format + " (VTK: " + error + ")");
}

/// The first `size` bytes of the file (fewer when it is shorter).
std::string file_start(const std::string& path, std::size_t size) {
    io::check_readable(path);
    std::ifstream in(path, std::ios::binary);
    std::string bytes(size, '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(size));
    bytes.resize(static_cast<std::size_t>(in.gcount()));
    return bytes;
}

/// Throws `PATH: not a text file` when `bytes` hold a NUL or another control character than
/// whitespace, before VTK reads what is not VTK at all (its messages echo the raw bytes).
void check_text(const std::string& path, std::string_view bytes, const char* format) {
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const auto c = static_cast<unsigned char>(bytes[i]);
        if ((c < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\v') ||
            c == 0x7f) {
            char byte[8];
            std::snprintf(byte, sizeof byte, "0x%02x", c);
            throw InputError(path + ": not a text file (byte " + byte + " at offset " +
                             std::to_string(i) + "), so not " + format +
                             ": a binary or compressed file?");
        }
    }
}

/// Legacy VTK files start with the line `# vtk DataFile Version x.y`.
void check_legacy_header(const std::string& path) {
    const std::string start = file_start(path, 256);
    if (start.compare(0, 3, "\xEF\xBB\xBF") == 0)
        throw InputError(path +
                         ":1: starts with a UTF-8 byte-order mark, which VTK's legacy "
                         "reader does not accept");
    const std::string_view first(start.data(), std::min(start.find('\n'), start.size()));
    check_text(path, first, "a legacy VTK file");
    if (first.rfind("# vtk DataFile Version", 0) != 0)
        throw InputError(path + ":1: expected '# vtk DataFile Version x.y', found " +
                         io::quote(first));
}

/// Whether `token` is a whole decimal integer (an optional sign, then at most 18 digits).
bool is_integer(std::string_view token) {
    std::size_t i = !token.empty() && (token[0] == '-' || token[0] == '+') ? 1 : 0;
    if (i == token.size() || token.size() - i > 18) return false;  // 18 digits fit a long long
    for (; i < token.size(); ++i) {
        if (!std::isdigit(static_cast<unsigned char>(token[i]))) return false;
    }
    return true;
}

/// Whether `token` is a whole decimal number as `std::istream >> double` reads it: a sign, digits
/// with at most one point, an exponent.
bool is_decimal_number(std::string_view token) {
    std::size_t i = !token.empty() && (token[0] == '-' || token[0] == '+') ? 1 : 0;
    std::size_t digits = 0;
    bool point = false;
    for (; i < token.size(); ++i) {
        if (std::isdigit(static_cast<unsigned char>(token[i])))
            ++digits;
        else if (token[i] == '.' && !point)
            point = true;
        else
            break;
    }
    if (digits == 0) return false;
    if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
        ++i;
        if (i < token.size() && (token[i] == '-' || token[i] == '+')) ++i;
        if (i == token.size()) return false;
        for (; i < token.size(); ++i) {
            if (!std::isdigit(static_cast<unsigned char>(token[i]))) return false;
        }
    }
    return i == token.size();
}

/// Whether `token` names the keyword `keyword` (lower case) as VTK's legacy reader sees it: VTK
/// lowercases what it reads and compares only the keyword's length (`strncmp`), so that
/// `POLyGONS` and `polygonsX` are both its POLYGONS.
bool is_vtk_keyword(std::string_view token, std::string_view keyword) {
    if (token.size() < keyword.size()) return false;
    for (std::size_t i = 0; i < keyword.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(token[i])) != keyword[i]) return false;
    }
    return true;
}

/// The cell sections of an ASCII legacy file (VERTICES, LINES, POLYGONS, TRIANGLE_STRIPS, CELLS,
/// in the classic `n size` layout before version 5 and 5.x's OFFSETS/CONNECTIVITY from version 5
/// on, and CELL_TYPES), checked before VTK reads them: VTK 9.1's reader dereferences a null string
/// when such a section is cut short or holds a non-number (a crash found by fuzzing). Each section
/// must hold as many integers as it declares, POINTS three numbers per point, and a FIELD section
/// before POINT_DATA and CELL_DATA as many numbers as its arrays declare. Keywords, the file type
/// and the version are read as VTK reads them (is_vtk_keyword; the type is the first word after the
/// title line, the version `%d.%d` after `# vtk DataFile Version`, 0 when there is none), so that
/// no spelling VTK accepts escapes the check. The scan stops at POINT_DATA or CELL_DATA (names
/// there are free text). Binary legacy files are left to VTK.
void check_legacy_cells(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string version_line, title, format;
    std::getline(in, version_line);
    std::getline(in, title);
    in >> format;
    if (!is_vtk_keyword(format, "ascii")) return;
    int major = 0, minor = 0;
    const std::string_view prefix = "# vtk DataFile Version";
    if (version_line.size() < prefix.size() ||
        std::sscanf(version_line.c_str() + prefix.size(), "%d.%d", &major, &minor) != 2)
        major = 0;
    const bool offsets_layout = major >= 5;
    std::vector<std::string> tokens;
    for (std::string token; in >> token;) {
        if (is_vtk_keyword(token, "point_data") || is_vtk_keyword(token, "cell_data")) break;
        tokens.push_back(std::move(token));
    }
    const auto fail = [&](const std::string& section, const std::string& what) {
        throw InputError(path + ": the " + section + " section " + what);
    };
    // Requires `count` integers from tokens[i] on; returns the index after them.
    const auto integers = [&](std::size_t i, long long count, const std::string& section) {
        if (count < 0 || i > tokens.size() ||
            static_cast<unsigned long long>(count) > tokens.size() - i)
            fail(section, "is cut short (" + std::to_string(count) + " numbers declared)");
        for (long long k = 0; k < count; ++k, ++i) {
            if (!is_integer(tokens[i]))
                fail(section, "holds " + io::quote(tokens[i].substr(0, 40)) +
                                  " where a whole number belongs");
        }
        return i;
    };
    // A count as VTK reads it: a whole number that fits.
    const auto count_at = [&](std::size_t i, const std::string& section, const char* what) {
        if (i >= tokens.size() || !is_integer(tokens[i]) || tokens[i].size() > 18)
            fail(section, std::string("has no ") + what);
        return std::stoll(tokens[i]);
    };
    static const char* const kCellSections[] = {"vertices", "lines", "polygons", "triangle_strips",
                                                "cells"};
    // The numeric array types of VTK's ReadArray (string and variant arrays are not read here).
    static const char* const kNumericTypes[] = {
        "bit",   "char",         "signed_char", "unsigned_char", "short",        "unsigned_short",
        "int",   "unsigned_int", "long",        "unsigned_long", "vtktypeint64", "vtktypeuint64",
        "float", "double",       "vtkidtype"};
    for (std::size_t i = 0; i < tokens.size();) {
        const std::string& token = tokens[i];
        const std::string section = token.substr(0, 40);
        if (is_vtk_keyword(token, "field")) {
            // FIELD NAME COUNT, then per array NAME COMPONENTS TUPLES TYPE and its values (or
            // NULL_ARRAY). VTK 9.1 dereferences the null field data its reader returns for a
            // malformed one here, before the points (a crash found by fuzzing).
            const long long arrays = count_at(i + 2, section, "'NAME COUNT' after its name");
            if (arrays < 0) fail(section, "declares " + std::to_string(arrays) + " arrays");
            i += 3;
            for (long long a = 0; a < arrays; ++a) {
                if (i < tokens.size() && tokens[i] == "NULL_ARRAY") {
                    ++i;
                    continue;
                }
                const std::string array = section + " array " + std::to_string(a);
                const long long components = count_at(i + 1, array, "'COMPONENTS TUPLES TYPE'");
                const long long tuples = count_at(i + 2, array, "'COMPONENTS TUPLES TYPE'");
                if (i + 3 >= tokens.size() ||
                    std::none_of(std::begin(kNumericTypes), std::end(kNumericTypes),
                                 [&](const char* k) { return is_vtk_keyword(tokens[i + 3], k); }))
                    fail(array, "has no numeric type (a string or variant array, or none)");
                if (components < 1 || tuples < 0 || components > (1LL << 31) ||
                    tuples > (1LL << 31))
                    fail(array, "declares " + std::to_string(components) + " components and " +
                                    std::to_string(tuples) + " tuples");
                i += 4;
                const long long values = components * tuples;
                if (static_cast<unsigned long long>(values) > tokens.size() - i)
                    fail(array, "is cut short (" + std::to_string(values) + " values declared)");
                for (long long k = 0; k < values; ++k, ++i) {
                    if (!is_decimal_number(tokens[i]))
                        fail(array, "holds " + io::quote(tokens[i].substr(0, 40)) +
                                        " where a number belongs");
                }
            }
            continue;
        }
        if (is_vtk_keyword(token, "points")) {
            // POINTS COUNT TYPE, then 3 COUNT numbers: VTK 9.1 reads a short section's next
            // word as a number and then dereferences what it did not read (`0.FieldData`: a
            // crash found by fuzzing).
            const long long points = count_at(i + 1, section, "'COUNT TYPE' after its name");
            if (i + 2 >= tokens.size() ||
                std::none_of(std::begin(kNumericTypes), std::end(kNumericTypes),
                             [&](const char* k) { return is_vtk_keyword(tokens[i + 2], k); }))
                fail(section, "has no numeric type");
            i += 3;
            if (points < 0 || points > (1LL << 31) ||
                static_cast<unsigned long long>(3 * points) > tokens.size() - i)
                fail(section, "is cut short (" + std::to_string(points) + " points declared)");
            for (long long k = 0; k < 3 * points; ++k, ++i) {
                if (!is_decimal_number(tokens[i]))
                    fail(section, "holds " + io::quote(tokens[i].substr(0, 40)) +
                                      " where a coordinate belongs");
            }
            continue;
        }
        if (is_vtk_keyword(token, "cell_types")) {
            i = integers(i + 2, count_at(i + 1, section, "count"), section);
            continue;
        }
        if (std::none_of(std::begin(kCellSections), std::end(kCellSections),
                         [&](const char* k) { return is_vtk_keyword(token, k); })) {
            ++i;
            continue;
        }
        const long long cells = count_at(i + 1, section, "'COUNT SIZE' after its name");
        const long long size = count_at(i + 2, section, "'COUNT SIZE' after its name");
        i += 3;
        if (!offsets_layout) {
            // `cells` cells, each its point count then its points: `size` numbers in all. VTK
            // walks them by the counts without checking (a crash found by fuzzing).
            const std::size_t first = i;
            i = integers(i, size, section);
            std::size_t k = first;
            for (long long c = 0; c < cells; ++c) {
                const long long points = k < i ? std::stoll(tokens[k]) : -1;
                if (points < 0 || static_cast<unsigned long long>(points) >= i - k)
                    fail(section, "does not hold " + std::to_string(cells) +
                                      " cells of 'COUNT POINTS...' in " + std::to_string(size) +
                                      " numbers");
                k += static_cast<std::size_t>(points) + 1;
            }
            if (k != i) fail(section, "holds more than its " + std::to_string(cells) + " cells");
            continue;
        }
        // Version 5: OFFSETS TYPE, `cells` offsets, CONNECTIVITY TYPE, `size` indices; the
        // offsets rise from 0 to `size`.
        if (i >= tokens.size() || !is_vtk_keyword(tokens[i], "offsets"))
            fail(section, "has no OFFSETS (a version 5 file)");
        const std::size_t first = i + 2;
        i = integers(i + 2, cells, section + " OFFSETS");
        for (std::size_t k = first; k < i; ++k) {
            const long long offset = std::stoll(tokens[k]);
            const long long before = k == first ? 0 : std::stoll(tokens[k - 1]);
            if (offset < before || offset > size || (k == first && offset != 0) ||
                (k + 1 == i && offset != size))
                fail(section + " OFFSETS", "do not rise from 0 to " + std::to_string(size));
        }
        if (i >= tokens.size() || !is_vtk_keyword(tokens[i], "connectivity"))
            fail(section, "has no CONNECTIVITY after its OFFSETS");
        i = integers(i + 2, size, section + " CONNECTIVITY");
    }
}

/// XML files start with '<' (after whitespace).
void check_xml_start(const std::string& path) {
    const std::string start = file_start(path, 256);
    std::size_t i = start.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    while (i < start.size() && std::isspace(static_cast<unsigned char>(start[i]))) ++i;
    const std::size_t end = std::min(start.find('>'), start.size());
    check_text(path, std::string_view(start).substr(0, end), "a VTU (XML) file");
    if (i >= start.size() || start[i] != '<')
        throw InputError(path + ": not a VTU (XML) file: it does not start with '<'");
}

MeshFile read_vtk_file(const std::string& path) {
    check_legacy_header(path);
    check_legacy_cells(path);
    auto reader = vtkSmartPointer<vtkDataSetReader>::New();
    // VTK's own dispatch on the DATASET keyword, before any dataset reader runs: only the two
    // mesh types are read (the structured-grid reader crashes on malformed metadata, found by
    // fuzz_vtk, tests/fuzz/regressions/vtk/structured-grid-metadata-segv).
    reader->SetFileName(path.c_str());
    int type = -1;
    std::string error;
    {
        VtkCapture capture;
        type = reader->ReadOutputType();
        error = capture.error();
    }
    if (!error.empty()) throw InputError(path + ": cannot read as legacy VTK (VTK: " + error + ")");
    if (type != VTK_UNSTRUCTURED_GRID && type != VTK_POLY_DATA) {
        const char* name = vtkDataObjectTypes::GetClassNameFromTypeId(type);
        throw InputError(path + ": dataset type " + (name ? name : "unknown") +
                         "; only UNSTRUCTURED_GRID and POLYDATA are supported");
    }
    run_reader(*reader, path, "legacy VTK");
    vtkDataSet* data = reader->GetOutput();
    if (data == nullptr) throw InputError(path + ": cannot read as legacy VTK");
    if (vtkUnstructuredGrid::SafeDownCast(data) == nullptr &&
        vtkPolyData::SafeDownCast(data) == nullptr)
        throw InputError(path + ": dataset type " + data->GetClassName() +
                         "; only UNSTRUCTURED_GRID and POLYDATA are supported");
    return to_mesh_file(path, data);
}

MeshFile read_vtu_file(const std::string& path) {
    check_xml_start(path);
    auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    run_reader(*reader, path, "VTU");
    vtkUnstructuredGrid* grid = reader->GetOutput();
    if (grid == nullptr) throw InputError(path + ": cannot read as VTU");
    return to_mesh_file(path, grid);
}

void write_vtk_file(const std::string& path, const Eigen::MatrixXd& positions,
                    const Eigen::MatrixXi& simplices, const std::vector<DataArray>& point_data,
                    const std::vector<DataArray>& cell_data) {
    check_arguments("write_vtk", positions, simplices, point_data, cell_data);
    // Written here rather than by vtkUnstructuredGridWriter, whose ASCII output rounds doubles to
    // 11 significant digits.
    AtomicFile file(path);
    std::ostream& out = file.stream();
    const Eigen::Index n = positions.rows(), m = simplices.rows(), k = simplices.cols();
    out << "# vtk DataFile Version 4.2\nsimplex-assembly\nASCII\nDATASET UNSTRUCTURED_GRID\n"
        << "POINTS " << n << " double\n";
    for (Eigen::Index i = 0; i < n; ++i) {
        io::write_position(out, positions, i, true);
        out << '\n';
    }
    out << "CELLS " << m << ' ' << m * (k + 1) << '\n';
    for (Eigen::Index e = 0; e < m; ++e) {
        out << k;
        for (Eigen::Index c = 0; c < k; ++c) out << ' ' << simplices(e, c);
        out << '\n';
    }
    out << "CELL_TYPES " << m << '\n';
    const int type = k == 4 ? VTK_TETRA : VTK_TRIANGLE;
    for (Eigen::Index e = 0; e < m; ++e) out << type << '\n';
    write_legacy_arrays(out, "POINT_DATA", n, point_data);
    write_legacy_arrays(out, "CELL_DATA", m, cell_data);
    file.commit();
}

void write_vtu_file(const std::string& path, const Eigen::MatrixXd& positions,
                    const Eigen::MatrixXi& simplices, const std::vector<DataArray>& point_data,
                    const std::vector<DataArray>& cell_data) {
    check_arguments("write_vtu", positions, simplices, point_data, cell_data);
    auto grid = make_grid(positions, simplices, point_data, cell_data);
    AtomicFile file(path);
    auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
    writer->SetFileName(file.temporary_path().c_str());
    writer->SetInputData(grid);
    int ok = 0;
    std::string error;
    {
        VtkCapture capture;
        ok = writer->Write();
        error = capture.error();
    }
    if (ok != 1 || !error.empty())
        throw InputError(path + ": cannot write" + (error.empty() ? "" : " (VTK: " + error + ")"));
    file.commit();
}

}  // namespace

}  // namespace sa

extern "C" const sa::VtkIoFunctions* sa_vtk_io_functions() {
    static const sa::VtkIoFunctions table{sa::read_vtk_file, sa::read_vtu_file, sa::write_vtk_file,
                                          sa::write_vtu_file};
    return &table;
}
