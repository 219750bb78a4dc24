#include "frontends/seamless/cone_obstruction.h"

#include <algorithm>

namespace sa {

std::string seamless_cone_obstruction(const SimplicialMesh& mesh, const MeshTopology& topology,
                                      const std::vector<Singularity>& singularities) {
    // A torus: connected, closed, Euler characteristic 0.
    Index components = 0;
    topology.simplex_components(&components);
    const bool closed = topology.boundary_facets.empty();
    Index vertices = 0;
    for (Index v = 0; v < mesh.num_vertices(); ++v) vertices += topology.used_vertex[v];
    const Index edges = static_cast<Index>(topology.interior_facets.size());
    const Index euler = vertices - edges + mesh.num_simplices();
    if (components != 1 || !closed || euler != 0 || singularities.size() != 2) return "";
    const double a = singularities[0].index, b = singularities[1].index;
    if (std::min(a, b) != -0.25 || std::max(a, b) != 0.25) return "";
    return "the field's only singularities on this torus are one of index +1/4 (vertex " +
           std::to_string(a > 0 ? singularities[0].vertex : singularities[1].vertex) +
           ") and one of index -1/4 (vertex " +
           std::to_string(a > 0 ? singularities[1].vertex : singularities[0].vertex) +
           "): no seamless parameterization has exactly these cones (a euclidean cone metric on "
           "the torus with cone angles 3 pi/2 and 5 pi/2 has no holonomy in the quarter turns: "
           "Izmestiev et al. 2013; the exception of Campen et al. 2019)";
}

}  // namespace sa
