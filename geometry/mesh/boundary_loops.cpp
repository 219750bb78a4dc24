#include "geometry/mesh/boundary_loops.h"

#include <algorithm>
#include <map>

#include "optim/errors.h"

namespace sa {

std::vector<std::vector<Index>> boundary_loops(const SimplicialMesh& mesh,
                                               const MeshTopology& topology) {
    // next[a] = b for every boundary edge a -> b in its triangle's order.
    std::map<Index, Index> next;
    for (const BoundaryFacet& f : topology.boundary_facets) {
        const Index a = f.vertices[0], b = f.vertices[1];
        Index from = a, to = b;
        for (int k = 0; k < 3; ++k) {
            if (mesh.simplices(f.simplex, k) == b && mesh.simplices(f.simplex, (k + 1) % 3) == a) {
                from = b;
                to = a;
            }
        }
        next[from] = to;
    }
    std::vector<std::vector<Index>> loops;
    std::map<Index, bool> done;
    for (const auto& [start, unused] : next) {
        (void)unused;
        if (done[start]) continue;
        std::vector<Index> loop;
        Index v = start;
        while (!done[v]) {
            done[v] = true;
            loop.push_back(v);
            const auto it = next.find(v);
            if (it == next.end()) break;
            v = it->second;
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

Index require_planar_surface(const SimplicialMesh& mesh, const MeshTopology& topology,
                             const std::string& source) {
    if (mesh.simplex_dimension() != 2)
        throw InputError(source + ": a parameterization needs a triangle mesh");
    Index used = 0;
    for (Index v = 0; v < mesh.num_vertices(); ++v) used += topology.used_vertex[v] ? 1 : 0;
    // A boundary vertex with two outgoing boundary edges makes the boundary non-manifold.
    std::vector<int> out_degree(mesh.num_vertices(), 0);
    for (const BoundaryFacet& f : topology.boundary_facets) {
        for (int k = 0; k < 2; ++k) {
            if (++out_degree[f.vertices[k]] > 2) {
                throw InputError(source + ": the mesh is not manifold at boundary vertex " +
                                 std::to_string(f.vertices[k]) +
                                 " (more than two boundary edges meet there)");
            }
        }
    }
    Index parts = 0;
    const std::vector<Index> part = topology.simplex_components(&parts);
    if (parts > 1) {
        const Index other = Index(
            std::find_if(part.begin(), part.end(), [](Index p) { return p != 0; }) - part.begin());
        throw InputError(source + ": the mesh has " + std::to_string(parts) +
                         " connected parts (triangles 0 and " + std::to_string(other) +
                         " are in different ones); a planar parameterization takes one at a time");
    }
    const Index loops = Index(boundary_loops(mesh, topology).size());
    if (loops == 0) {
        throw InputError(source +
                         ": the mesh is closed (no boundary); a planar parameterization needs a "
                         "disk: cut it open first");
    }
    const long chi = long(used) - long(topology.edges.size()) + long(mesh.num_simplices());
    if (chi != 2 - loops) {
        const long genus = (2 - long(loops) - chi) / 2;
        throw InputError(source + ": Euler characteristic " + std::to_string(chi) + " with " +
                         std::to_string(loops) + " boundary loop" + (loops == 1 ? "" : "s") +
                         " (genus " + std::to_string(genus) +
                         "): the surface has handles; a planar parameterization needs genus 0: "
                         "cut it to a disk first");
    }
    return loops;
}

void require_disk(const SimplicialMesh& mesh, const MeshTopology& topology,
                  const std::string& source) {
    const Index loops = require_planar_surface(mesh, topology, source);
    if (loops > 1) {
        throw InputError(source + ": the mesh has " + std::to_string(loops) +
                         " boundary loops; this needs one (a disk)");
    }
}

}  // namespace sa
