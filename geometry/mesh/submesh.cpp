#include "geometry/mesh/submesh.h"

#include <algorithm>
#include <numeric>

namespace sa {

std::vector<Index> grow_rings(const SimplicialMesh& mesh, const MeshTopology& topology,
                              const std::vector<Index>& seeds, int rings) {
    std::vector<unsigned char> in(mesh.num_simplices(), 0), vertex_done(mesh.num_vertices(), 0);
    std::vector<Index> current;
    for (Index s : seeds) {
        if (!in[s]) in[s] = 1, current.push_back(s);
    }
    std::vector<Index> frontier = current;
    for (int r = 0; r < rings; ++r) {
        std::vector<Index> next;
        for (Index s : frontier) {
            for (int k = 0; k < mesh.simplices.cols(); ++k) {
                const Index v = mesh.simplices(s, k);
                if (vertex_done[v]) continue;
                vertex_done[v] = 1;
                for (Index i = topology.vertex_begin[v]; i < topology.vertex_begin[v + 1]; ++i) {
                    const Index t = topology.simplices_of_vertex[i];
                    if (!in[t]) in[t] = 1, next.push_back(t);
                }
            }
        }
        if (next.empty()) break;
        current.insert(current.end(), next.begin(), next.end());
        frontier.swap(next);
    }
    std::sort(current.begin(), current.end());
    return current;
}

std::vector<Index> fill_enclosed(const MeshTopology& topology, const std::vector<Index>& region) {
    const int d = topology.dimension;
    const Index n = static_cast<Index>(topology.neighbour.size() / (d + 1));
    // Components of the rest: -2 in the region, -1 not visited yet, else the component's number.
    // Only each component's size, seed and whether it reaches the boundary are kept: the rest is
    // most of the mesh, and a small region usually leaves one component, the outside.
    std::vector<Index> rest(n, -1);
    for (Index s : region) rest[s] = -2;
    struct Component {
        Index seed = 0, size = 0;
        bool reaches_boundary = false;
    };
    std::vector<Component> components;
    std::vector<Index> stack;
    for (Index seed = 0; seed < n; ++seed) {
        if (rest[seed] != -1) continue;
        Component c{seed};
        rest[seed] = static_cast<Index>(components.size());
        stack.push_back(seed);
        while (!stack.empty()) {
            const Index s = stack.back();
            stack.pop_back();
            ++c.size;
            for (int k = 0; k <= d; ++k) {
                const Index t = topology.neighbour_of(s, k);
                if (t < 0) {
                    c.reaches_boundary = true;
                } else if (rest[t] == -1) {
                    rest[t] = rest[seed];
                    stack.push_back(t);
                }
            }
        }
        components.push_back(c);
    }
    std::vector<Index> filled = region;
    const bool all_reach_boundary =
        std::all_of(components.begin(), components.end(),
                    [](const Component& c) { return c.reaches_boundary; });
    if (!all_reach_boundary) {
        // Which part of the mesh each component lies in, and whether that part has a boundary:
        // in a part without boundary the largest component of the rest is the outside.
        Index mesh_parts = 0;
        const std::vector<Index> mesh_part = topology.simplex_components(&mesh_parts);
        std::vector<unsigned char> part_has_boundary(mesh_parts, 0);
        for (const BoundaryFacet& f : topology.boundary_facets)
            part_has_boundary[mesh_part[f.simplex]] = 1;
        std::vector<Index> largest(mesh_parts, -1);
        for (std::size_t c = 0; c < components.size(); ++c) {
            const Index part = mesh_part[components[c].seed];
            if (!part_has_boundary[part] &&
                (largest[part] < 0 || components[c].size > components[largest[part]].size))
                largest[part] = static_cast<Index>(c);
        }
        std::vector<unsigned char> enclosed(components.size(), 0);
        for (std::size_t c = 0; c < components.size(); ++c) {
            enclosed[c] = !components[c].reaches_boundary &&
                          largest[mesh_part[components[c].seed]] != Index(c);
        }
        for (Index s = 0; s < n; ++s) {
            if (rest[s] >= 0 && enclosed[rest[s]]) filled.push_back(s);
        }
    }
    std::sort(filled.begin(), filled.end());
    return filled;
}

std::vector<std::vector<Index>> vertex_connected_regions(const SimplicialMesh& mesh,
                                                         const MeshTopology& topology,
                                                         const std::vector<Index>& simplices) {
    std::vector<Index> region(mesh.num_simplices(), -2);  // -2: not in the set
    for (Index s : simplices) region[s] = -1;
    std::vector<std::vector<Index>> regions;
    for (Index seed : simplices) {  // ascending: regions ordered by their smallest simplex
        if (region[seed] != -1) continue;
        const Index id = static_cast<Index>(regions.size());
        std::vector<Index> members{seed}, stack{seed};
        region[seed] = id;
        while (!stack.empty()) {
            const Index s = stack.back();
            stack.pop_back();
            for (int k = 0; k < mesh.simplices.cols(); ++k) {
                const Index v = mesh.simplices(s, k);
                for (Index i = topology.vertex_begin[v]; i < topology.vertex_begin[v + 1]; ++i) {
                    const Index t = topology.simplices_of_vertex[i];
                    if (region[t] == -1) {
                        region[t] = id;
                        members.push_back(t);
                        stack.push_back(t);
                    }
                }
            }
        }
        std::sort(members.begin(), members.end());
        regions.push_back(std::move(members));
    }
    return regions;
}

Submesh extract_submesh(const SimplicialMesh& mesh, const MeshTopology& topology,
                        const std::vector<Index>& simplices) {
    Submesh sub;
    sub.simplices = simplices;
    std::vector<Index> local(mesh.num_vertices(), -1);
    std::vector<unsigned char> in(mesh.num_simplices(), 0);
    for (Index s : simplices) {
        in[s] = 1;
        for (int k = 0; k < mesh.simplices.cols(); ++k) {
            const Index v = mesh.simplices(s, k);
            if (local[v] < 0) {
                local[v] = static_cast<Index>(sub.vertices.size());
                sub.vertices.push_back(v);
            }
        }
    }
    sub.mesh.vertices.resize(sub.vertices.size(), mesh.vertices.cols());
    for (std::size_t i = 0; i < sub.vertices.size(); ++i)
        sub.mesh.vertices.row(i) = mesh.vertices.row(sub.vertices[i]);
    sub.mesh.simplices.resize(simplices.size(), mesh.simplices.cols());
    for (std::size_t j = 0; j < simplices.size(); ++j) {
        for (int k = 0; k < mesh.simplices.cols(); ++k)
            sub.mesh.simplices(j, k) = local[mesh.simplices(simplices[j], k)];
    }
    sub.on_region_boundary.assign(sub.vertices.size(), 0);
    for (std::size_t i = 0; i < sub.vertices.size(); ++i) {
        const Index v = sub.vertices[i];
        for (Index p = topology.vertex_begin[v]; p < topology.vertex_begin[v + 1]; ++p) {
            if (!in[topology.simplices_of_vertex[p]]) {
                sub.on_region_boundary[i] = 1;
                break;
            }
        }
    }
    return sub;
}

std::vector<int> greedy_coloring(const std::vector<std::vector<Index>>& adjacency) {
    std::vector<int> color(adjacency.size(), -1);
    std::vector<char> used;
    for (std::size_t i = 0; i < adjacency.size(); ++i) {
        used.assign(adjacency[i].size() + 1, 0);
        for (Index j : adjacency[i]) {
            if (color[j] >= 0 && color[j] < int(used.size())) used[color[j]] = 1;
        }
        int c = 0;
        while (used[c]) ++c;
        color[i] = c;
    }
    return color;
}

}  // namespace sa
