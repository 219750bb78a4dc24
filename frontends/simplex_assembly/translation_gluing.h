#pragma once
// Recovery of the translations T_i that r-SA does not carry (Appendix: "variable reduction"):
// starting from simplices whose T is known, each neighbour across a shared facet is translated so
// that the images of the facet's vertices coincide (their mean when the assembly is not exact),
// breadth-first until every simplex is placed. A connected component with no known simplex starts
// from `fallback` for its lowest-numbered simplex.

#include <utility>
#include <vector>

#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/rest_frames.h"

namespace sa {

template <int D>
std::vector<Vec<D>> glue_translations(const SimplicialMesh& mesh, const MeshTopology& topology,
                                      const RestFrames<D>& frames, const std::vector<Mat<D>>& A,
                                      const std::vector<std::pair<Index, Vec<D>>>& known,
                                      const std::vector<Vec<D>>& fallback);

}  // namespace sa
