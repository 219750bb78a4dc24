#pragma once
// Internal to geometry/io: a VTK dataset's points and cells (as the legacy reader and the VTU
// plugin read them) turned into a MeshFile, with the checks both readers share.

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/io/mesh_file.h"

namespace sa::io {

/// VTK's cell type ids that the readers name in messages.
enum VtkCellType : int { kVtkTriangle = 5, kVtkTetra = 10 };

/// `5 (vtkTriangle)`: a VTK cell type id with VTK's class name for it ("unknown" when it has
/// none).
std::string vtk_cell_type_name(int type);

/// Points and cells as VTK stores them: cell c has type `types[c]` and the points
/// `connectivity[offsets[c] .. offsets[c+1])`.
struct VtkCells {
    std::vector<int> types;
    std::vector<std::int64_t> offsets{0};  // #cells + 1, rising from 0 to connectivity.size()
    std::vector<std::int64_t> connectivity;
};

/// The mesh of `points` (#P x 3) and `cells`: their tetrahedra (10) when there are any, else
/// their triangles (5); vertices, lines and, beside tetrahedra, triangles are skipped with a
/// warning (a Gmsh export holds them), indices in range, coordinates finite. A triangle mesh
/// whose z coordinates are all 0 is read as 2D. Throws InputError `PATH: cell C has type ...`
/// (another type: quads, hexahedra, ...; or `refers to point ...`, `point I has a non-finite
/// coordinate`) naming the first offending element.
MeshFile mesh_from_vtk_cells(const std::string& path, const Eigen::MatrixXd& points,
                             const VtkCells& cells);

}  // namespace sa::io
