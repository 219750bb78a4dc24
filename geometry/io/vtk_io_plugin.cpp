#include "geometry/io/vtk_io_plugin.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
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
#include "geometry/io/byte_cursor.h"
#include "geometry/io/text_reader.h"
#include "geometry/io/vtk_capture.h"
#include "geometry/io/vtk_cells.h"
#include "geometry/io/write_checks.h"
#include "optim/errors.h"

namespace sa {
namespace {

MeshFile to_mesh_file(const std::string& path, vtkDataSet* data) {
    const vtkIdType num_points = data->GetNumberOfPoints();
    const vtkIdType num_cells = data->GetNumberOfCells();
    if (num_points > std::numeric_limits<int>::max() || num_cells > std::numeric_limits<int>::max())
        throw InputError(path + ": too many points or cells");
    Eigen::MatrixXd points(num_points, 3);
    for (vtkIdType i = 0; i < num_points; ++i) {
        double p[3];
        data->GetPoint(i, p);
        for (int j = 0; j < 3; ++j) points(i, j) = p[j];
    }
    io::VtkCells cells;
    cells.types.reserve(static_cast<std::size_t>(num_cells));
    auto ids = vtkSmartPointer<vtkIdList>::New();
    for (vtkIdType c = 0; c < num_cells; ++c) {
        cells.types.push_back(data->GetCellType(c));
        data->GetCellPoints(c, ids);
        for (vtkIdType j = 0; j < ids->GetNumberOfIds(); ++j)
            cells.connectivity.push_back(ids->GetId(j));
        cells.offsets.push_back(static_cast<std::int64_t>(cells.connectivity.size()));
    }
    return io::mesh_from_vtk_cells(path, points, cells);
}

// The VTK cell type of rows of `columns` vertex indices: 3, 4 or 8 (checked).
int cell_type(Eigen::Index columns) {
    return columns == 8 ? VTK_HEXAHEDRON : columns == 4 ? VTK_TETRA : VTK_TRIANGLE;
}

// Checks a writer's arguments; throws InvalidArgumentError naming `function`.
void check_arguments(const char* function, const Eigen::MatrixXd& positions,
                     const Eigen::MatrixXi& simplices, const std::vector<DataArray>& point_data,
                     const std::vector<DataArray>& cell_data) {
    io::check_positions(function, positions);
    const bool hexahedra = simplices.cols() == 8;
    io::check_simplices(function, hexahedra ? "hexahedra" : "simplices", simplices,
                        positions.rows(), hexahedra ? 8 : 0);
    if (simplices.cols() >= 4 && positions.cols() != 3) {
        throw InvalidArgumentError(std::string(function) + ": " +
                                   (hexahedra ? "hexahedra" : "tetrahedra") + " need 3D positions");
    }
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
    vtkIdType ids[8];
    for (Eigen::Index e = 0; e < simplices.rows(); ++e) {
        for (Eigen::Index c = 0; c < simplices.cols(); ++c) ids[c] = simplices(e, c);
        cells->InsertNextCell(simplices.cols(), ids);
    }
    grid->SetCells(cell_type(simplices.cols()), cells);

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
    const std::size_t bad = io::first_control_byte(bytes);
    if (bad != std::string_view::npos)
        throw InputError(path + ": " + io::control_byte_message(bytes, bad) + ", so not " + format +
                         ": a binary or compressed file?");
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
    const int type = cell_type(k);
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
    static const sa::VtkIoFunctions table{sa::read_vtu_file, sa::write_vtk_file,
                                          sa::write_vtu_file};
    return &table;
}
