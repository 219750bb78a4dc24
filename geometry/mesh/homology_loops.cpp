#include "geometry/mesh/homology_loops.h"

#include <algorithm>
#include <queue>
#include <utility>

#include "geometry/detail/union_find.h"

namespace sa {

std::vector<std::vector<Index>> homology_loops(Index num_vertices,
                                               const std::vector<std::array<Index, 3>>& triangles) {
    const Index num_triangles = static_cast<Index>(triangles.size());
    // Each edge once, with the triangles around it: (a, b, triangle) sorted by edge.
    struct Side {
        Index a, b, triangle;
    };
    std::vector<Side> sides;
    sides.reserve(3 * triangles.size());
    for (Index t = 0; t < num_triangles; ++t) {
        for (int k = 0; k < 3; ++k) {
            const Index a = triangles[t][k], b = triangles[t][(k + 1) % 3];
            sides.push_back({std::min(a, b), std::max(a, b), t});
        }
    }
    std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
        return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.triangle < y.triangle;
    });
    std::vector<std::size_t> edge_begin;  // edge e: sides[edge_begin[e] .. edge_begin[e + 1])
    for (std::size_t i = 0; i < sides.size(); ++i) {
        if (i == 0 || sides[i].a != sides[i - 1].a || sides[i].b != sides[i - 1].b)
            edge_begin.push_back(i);
    }
    const Index num_edges = static_cast<Index>(edge_begin.size());
    edge_begin.push_back(sides.size());

    // The vertex graph, compressed.
    std::vector<Index> adjacency_begin(num_vertices + 1, 0), adjacency;
    for (Index e = 0; e < num_edges; ++e) {
        ++adjacency_begin[sides[edge_begin[e]].a + 1];
        ++adjacency_begin[sides[edge_begin[e]].b + 1];
    }
    for (Index v = 0; v < num_vertices; ++v) adjacency_begin[v + 1] += adjacency_begin[v];
    adjacency.resize(adjacency_begin[num_vertices]);
    {
        std::vector<Index> fill(adjacency_begin.begin(), adjacency_begin.end() - 1);
        for (Index e = 0; e < num_edges; ++e) {
            adjacency[fill[sides[edge_begin[e]].a]++] = e;
            adjacency[fill[sides[edge_begin[e]].b]++] = e;
        }
    }

    // Breadth-first primal trees, one per component, from its lowest-numbered vertex.
    std::vector<Index> parent(num_vertices, -1), depth(num_vertices, -1);
    std::vector<unsigned char> in_tree(num_edges, 0);
    for (Index root = 0; root < num_vertices; ++root) {
        if (depth[root] >= 0 || adjacency_begin[root] == adjacency_begin[root + 1]) continue;
        depth[root] = 0;
        std::queue<Index> queue;
        queue.push(root);
        while (!queue.empty()) {
            const Index v = queue.front();
            queue.pop();
            for (Index i = adjacency_begin[v]; i < adjacency_begin[v + 1]; ++i) {
                const Index e = adjacency[i];
                const Side& s = sides[edge_begin[e]];
                const Index w = s.a == v ? s.b : s.a;
                if (depth[w] >= 0) continue;
                depth[w] = depth[v] + 1;
                parent[w] = v;
                in_tree[e] = 1;
                queue.push(w);
            }
        }
    }

    // The dual forest; node num_triangles stands for the boundary.
    UnionFind dual(num_triangles + 1);
    std::vector<std::vector<Index>> loops;
    for (Index e = 0; e < num_edges; ++e) {
        if (in_tree[e]) continue;
        const std::size_t first = edge_begin[e], count = edge_begin[e + 1] - first;
        const Index t0 = sides[first].triangle;
        const Index t1 = count == 1 ? num_triangles : sides[first + 1].triangle;
        if (dual.join(t0, t1)) continue;
        // A loop: up from a to the common ancestor, then down to b; the edge b a closes it.
        Index a = sides[first].a, b = sides[first].b;
        std::vector<Index> up, down;
        while (depth[a] > depth[b]) up.push_back(std::exchange(a, parent[a]));
        while (depth[b] > depth[a]) down.push_back(std::exchange(b, parent[b]));
        while (a != b) {
            up.push_back(std::exchange(a, parent[a]));
            down.push_back(std::exchange(b, parent[b]));
        }
        up.push_back(a);
        up.insert(up.end(), down.rbegin(), down.rend());
        loops.push_back(std::move(up));
    }
    return loops;
}

}  // namespace sa
