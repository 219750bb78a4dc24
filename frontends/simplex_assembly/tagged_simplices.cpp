#include "frontends/simplex_assembly/tagged_simplices.h"

#include <algorithm>

#include "optim/errors.h"

namespace sa {

std::vector<Index> simplices_with_edge(const SimplicialMesh& mesh, const MeshTopology& topology,
                                       Index a, Index b) {
    std::vector<Index> result;
    for (Index i = topology.vertex_begin[a]; i < topology.vertex_begin[a + 1]; ++i) {
        const Index s = topology.simplices_of_vertex[i];
        for (int k = 0; k < mesh.simplices.cols(); ++k) {
            if (mesh.simplices(s, k) == b) result.push_back(s);
        }
    }
    std::sort(result.begin(), result.end());
    return result;
}

std::vector<Index> tag_simplices(const SimplicialMesh& mesh, const MeshTopology& topology,
                                 const std::vector<GraphEdge>& tree_edges) {
    std::vector<unsigned char> tagged(mesh.num_simplices(), 0);
    std::vector<Index> result;
    result.reserve(tree_edges.size());
    for (const GraphEdge& e : tree_edges) {
        const std::vector<Index> candidates = simplices_with_edge(mesh, topology, e[0], e[1]);
        if (candidates.empty()) {
            throw InvalidArgumentError("tag_simplices: no simplex contains edge (" +
                                       std::to_string(e[0]) + ", " + std::to_string(e[1]) + ")");
        }
        Index pick = candidates.front();
        for (Index s : candidates) {
            if (tagged[s]) {
                pick = s;
                break;
            }
        }
        tagged[pick] = 1;
        result.push_back(pick);
    }
    return result;
}

}  // namespace sa
