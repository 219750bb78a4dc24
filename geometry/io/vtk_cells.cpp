#include "geometry/io/vtk_cells.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "optim/errors.h"

namespace sa::io {

std::string vtk_cell_type_name(int type) {
    // VTK's class names for its linear cell types and the common quadratic ones
    // (vtkCellType.h).
    static const char* const kLinear[] = {
        "vtkEmptyCell",       "vtkVertex",        "vtkPolyVertex", "vtkLine",  "vtkPolyLine",
        "vtkTriangle",        "vtkTriangleStrip", "vtkPolygon",    "vtkPixel", "vtkQuad",
        "vtkTetra",           "vtkVoxel",         "vtkHexahedron", "vtkWedge", "vtkPyramid",
        "vtkPentagonalPrism", "vtkHexagonalPrism"};
    static const char* const kQuadratic[] = {"vtkQuadraticEdge", "vtkQuadraticTriangle",
                                             "vtkQuadraticQuad", "vtkQuadraticTetra",
                                             "vtkQuadraticHexahedron"};
    const char* name = "unknown";
    if (type >= 0 && type <= 16)
        name = kLinear[type];
    else if (type >= 21 && type <= 25)
        name = kQuadratic[type - 21];
    else if (type == 42)
        name = "vtkPolyhedron";
    return std::to_string(type) + " (" + name + ")";
}

MeshFile mesh_from_vtk_cells(const std::string& path, const Eigen::MatrixXd& points,
                             const VtkCells& cells) {
    const std::size_t num_cells = cells.types.size();
    if (points.rows() > std::numeric_limits<int>::max() ||
        num_cells > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw InputError(path + ": too many points or cells");
    if (cells.offsets.size() != num_cells + 1)
        throw InputError(path + ": " + std::to_string(num_cells) + " cell types for " +
                         std::to_string(cells.offsets.size() - 1) + " cells");

    // The mesh is made of the tetrahedra when there are any, else of the triangles. Cells of a
    // lower dimension (vertices, lines, and triangles beside tetrahedra: what Gmsh writes for the
    // boundary and the geometry's points and curves) are skipped with a warning; any other cell
    // type is an error.
    const auto lower_dimensional = [](int t) { return t >= 1 && t <= 4; };  // vertex ... poly line
    const bool tets =
        std::find(cells.types.begin(), cells.types.end(), kVtkTetra) != cells.types.end();
    const int type = tets ? kVtkTetra : kVtkTriangle;
    std::size_t kept = 0;
    for (std::size_t c = 0; c < num_cells; ++c) {
        const int t = cells.types[c];
        if (t == type) {
            ++kept;
        } else if (!lower_dimensional(t) && !(tets && t == kVtkTriangle)) {
            throw InputError(path + ": cell " + std::to_string(c) + " has type " +
                             vtk_cell_type_name(t) +
                             "; only triangles (5) or tetrahedra (10) are read (and vertices, "
                             "lines and, beside tetrahedra, triangles skipped)");
        }
    }
    if (kept == 0 && num_cells > 0)
        throw InputError(path + ": no triangles or tetrahedra; cell 0 has type " +
                         vtk_cell_type_name(cells.types[0]));
    const int k = type == kVtkTetra ? 4 : 3;

    MeshFile result;
    SimplicialMesh& mesh = result.mesh;
    bool flat = type == kVtkTriangle;
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        for (int j = 0; j < 3; ++j) {
            if (!std::isfinite(points(i, j)))
                throw InputError(path + ": point " + std::to_string(i) +
                                 " has a non-finite coordinate");
        }
        if (points(i, 2) != 0.0) flat = false;
    }
    mesh.vertices = flat ? Eigen::MatrixXd(points.leftCols(2)) : points;

    mesh.simplices.resize(static_cast<Eigen::Index>(kept), k);
    Eigen::Index row = 0;
    for (std::size_t c = 0; c < num_cells; ++c) {
        const std::int64_t begin = cells.offsets[c], size = cells.offsets[c + 1] - begin;
        if (begin < 0 || size < 0 ||
            cells.offsets[c + 1] > static_cast<std::int64_t>(cells.connectivity.size()))
            throw InputError(path + ": the offsets of cell " + std::to_string(c) +
                             " are out of order or past the connectivity");
        if (cells.types[c] != type) continue;
        if (size != k)
            throw InputError(path + ": cell " + std::to_string(c) + " has " + std::to_string(size) +
                             " points; expected " + std::to_string(k));
        for (int j = 0; j < k; ++j) {
            const std::int64_t v = cells.connectivity[static_cast<std::size_t>(begin + j)];
            if (v < 0 || v >= points.rows())
                throw InputError(path + ": cell " + std::to_string(c) + " refers to point " +
                                 std::to_string(v) + ", out of range [0, " +
                                 std::to_string(points.rows() - 1) + "]");
            mesh.simplices(row, j) = static_cast<int>(v);
        }
        ++row;
    }
    if (kept < num_cells)
        result.warnings.push_back(path + ": skipped " + std::to_string(num_cells - kept) +
                                  " lower-dimensional cells (vertices, lines" +
                                  (tets ? ", triangles" : "") + "); read the " +
                                  std::to_string(kept) + (tets ? " tetrahedra" : " triangles"));
    return result;
}

}  // namespace sa::io
