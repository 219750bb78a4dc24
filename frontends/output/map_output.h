#pragma once
// Writing a Simplex Assembly result.
//
// write_map_result() chooses the format by extension. .vtu and .vtk carry, for ParaView:
//   cell data   det_J (det A_i of the output), conformal, isometric, volumetric (the paper's
//               delta metrics; -1 where undefined: inverted or degenerate simplices), inverted
//               (0/1)
//   point data  displacement (output - rest, when the map has the rest's dimension),
//               change (output - initial map), handle (0/1)
// Other extensions: write_mesh_file() (.obj, .off, .mesh, .node/.ele, or result records with
// `resV` for anything else). 2D maps are written with z = 0 where a format needs 3 coordinates.

#include <string>
#include <vector>

#include "frontends/simplex_assembly/map_solve.h"
#include "geometry/io/vtk_io.h"

namespace sa {

void write_map_result(const std::string& path, const MappingProblem& problem,
                      const SimplexAssemblyResult& result);

/// The cell data described above, for any map with per-simplex quality `quality`.
std::vector<DataArray> quality_cell_data(const MapQuality& quality);

}  // namespace sa
