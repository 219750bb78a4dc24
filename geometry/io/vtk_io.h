#pragma once
// VTK meshes: legacy .vtk (UNSTRUCTURED_GRID or POLYDATA, ASCII or BINARY, the classic and the
// version 5 cell layouts) and XML .vtu (unstructured grid).
//
// Read: the VTK_TETRA (10) cells when there are any, else the VTK_TRIANGLE (5) cells; vertices,
// lines and, beside tetrahedra, triangles are skipped with a warning (what a Gmsh export holds),
// any other cell type is an error. A triangle mesh whose z coordinates are all 0 is read as 2D.
// Written: an unstructured grid with double-precision points (2D positions padded with z = 0), the
// cells, and optional point and cell data arrays; .vtk in ASCII with the classic
// `CELLS`/`CELL_TYPES` layout (legacy file version 4.2, which older readers understand) and 17
// significant digits (written here: VTK's legacy writer rounds to 11), arrays as `FIELD` data; .vtu
// by VTK, binary appended (VTK's default, zlib-compressed).
//
// Legacy files are read here without VTK (geometry/io/legacy_vtk_reader.cpp: VTK's own legacy
// readers trust the file's counts). The rest goes through the VTK library, loaded on the first
// call: the implementation is the plugin libsa_vtk_io.so (geometry/io/vtk_io_plugin.h,
// geometry/io/plugin_library.h); a program that reads and writes other formats never loads VTK.
// Error when the plugin cannot be loaded. VTK reports problems through its global output window;
// these functions capture that text while they run (VtkCapture, geometry/io/vtk_capture.h:
// nothing is printed) and turn errors into exceptions.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "geometry/io/mesh_file.h"

namespace sa {

/// A named data array: one row per point (or cell), one column per component.
struct DataArray {
    std::string name;
    Eigen::MatrixXd values;
    /// Written as vtkIntArray (values must then be integers) instead of vtkDoubleArray.
    bool integer = false;
};

/// Reads a legacy .vtk file into `mesh`: vertices #V x 3 (#V x 2 for a triangle mesh with all
/// z = 0), simplices #S x 3 or #S x 4; the file's POINT_DATA and CELL_DATA are not read. Throws
/// InputError `FILE:LINE: ...` (`FILE: byte N: ...` in a binary file's data) naming what is
/// malformed: a section cut short or holding a non-number, a count the file cannot hold, another
/// dataset type, the first cell of a type that is not read (a quad, a hexahedron, ...) and its
/// type, an index out of range.
MeshFile read_vtk(const std::string& path);

/// Reads an XML .vtu file, as read_vtk(); errors carry VTK's message.
MeshFile read_vtu(const std::string& path);

/// Loads the plugin that reads and writes VTK files (libsa_vtk_io.so), which the functions here
/// otherwise do on first use; throws Error naming the library, the folders tried and the loader's
/// message when it cannot be loaded. For a check before a long run that writes VTK files.
void require_vtk_io();

/// Writes a legacy ASCII .vtk unstructured grid: `positions` #V x 2 or #V x 3, `simplices`
/// #S x 3 (VTK_TRIANGLE), #S x 4 (VTK_TETRA) or #S x 8 (VTK_HEXAHEDRON, in
/// geometry/mesh/hex_mesh.h's corner order; these two 3D only), `point_data` arrays of #V rows and
/// `cell_data` arrays of #S rows (non-empty, distinct names). Throws InvalidArgumentError on
/// arrays of the wrong shape, an index out of range, a non-integer value in an integer array or a
/// bad array name, and InputError when the file cannot be written (nothing is left at `path`
/// then).
void write_vtk(const std::string& path, const Eigen::MatrixXd& positions,
               const Eigen::MatrixXi& simplices, const std::vector<DataArray>& point_data = {},
               const std::vector<DataArray>& cell_data = {});

/// Writes an XML .vtu unstructured grid (binary, appended), as write_vtk().
void write_vtu(const std::string& path, const Eigen::MatrixXd& positions,
               const Eigen::MatrixXi& simplices, const std::vector<DataArray>& point_data = {},
               const std::vector<DataArray>& cell_data = {});

}  // namespace sa
