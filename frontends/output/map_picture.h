#pragma once
// The picture `sa map` writes beside its map: what a user looks at before opening ParaView.
//   2D: the initial map and the result side by side (layout_picture.h), each triangle coloured by
//       its conformal distortion sigma_max / sigma_min, inverted and degenerate ones in red;
//   3D: the result's boundary surface (pose_picture.h), coloured by the isometric distortion
//       max(sigma_max, 1 / sigma_min) of the tetrahedra under it, the tetrahedra inverted in the
//       initial map or in the result drawn whole in red and seen through the surface.
// The qualities come from the result (`initial_quality`, `final_quality`): nothing is solved.

#include <string>

#include "frontends/simplex_assembly/map_solve.h"

namespace sa {

struct MapPicture {
    int size = 1200;  ///< 2D: the longer side of each layout's panel; 3D: the width (4:3)
};

/// Writes `path` (PNG). Throws InvalidArgumentError when the problem is neither triangles mapped
/// to the plane nor tetrahedra in space; otherwise as write_layouts_png (2D) or write_pose_png
/// (3D: InputError when there is no X display and no Xvfb to render on).
void write_map_png(const std::string& path, const MappingProblem& problem,
                   const SimplexAssemblyResult& result, const MapPicture& picture = {});

}  // namespace sa
