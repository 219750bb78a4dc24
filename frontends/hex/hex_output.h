#pragma once
// The files of a hex mesh (issue 48), in the input's frame and units:
//   OUT.mesh   Medit `Hexahedra` (geometry/io/medit_io.h), what hex-mesh tools read;
//   a .vtu     VTK_HEXAHEDRON cells with cell data scaled_jacobian and min_corner_jacobian;
//   a .png     the boundary of the hexes below the middle of z, seen from above (the cut shows
//              the inside), each face coloured by its hex's 1 - scaled Jacobian from 0 (a
//              cuboid) up; inverted hexes in red.

#include <string>

#include "geometry/mesh/hex_mesh.h"
#include "geometry/quality/hex_quality.h"

namespace sa {

void write_hex_medit(const std::string& path, const HexMesh& mesh);

/// `quality` from hex_quality() on `mesh`.
void write_hex_vtu(const std::string& path, const HexMesh& mesh, const HexQuality& quality);

/// The picture described above, titled `title`.
void write_hex_png(const std::string& path, const HexMesh& mesh, const HexQuality& quality,
                   const std::string& title);

}  // namespace sa
