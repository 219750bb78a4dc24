#include "frontends/simplex_assembly/steiner_tree.h"

#include <algorithm>
#include <numeric>
#include <queue>

#include "geometry/detail/union_find.h"

namespace sa {

namespace {

struct Adjacency {
    std::vector<Index> begin, neighbours;
    Adjacency(Index n, const std::vector<GraphEdge>& edges) : begin(n + 1, 0) {
        for (const GraphEdge& e : edges) ++begin[e[0] + 1], ++begin[e[1] + 1];
        std::partial_sum(begin.begin(), begin.end(), begin.begin());
        neighbours.resize(begin[n]);
        std::vector<Index> cursor(begin.begin(), begin.end() - 1);
        for (const GraphEdge& e : edges) {
            neighbours[cursor[e[0]]++] = e[1];
            neighbours[cursor[e[1]]++] = e[0];
        }
        for (Index v = 0; v < n; ++v)
            std::sort(neighbours.begin() + begin[v], neighbours.begin() + begin[v + 1]);
    }
};

GraphEdge sorted(Index a, Index b) {
    return {std::min(a, b), std::max(a, b)};
}

}  // namespace

std::vector<GraphEdge> approximate_steiner_tree(Index n, const std::vector<GraphEdge>& edges,
                                                const std::vector<Index>& terminals) {
    const Adjacency graph(n, edges);
    std::vector<unsigned char> terminal(n, 0);
    for (Index t : terminals) terminal[t] = 1;

    // 1. Groups: components of the subgraph of terminal-terminal edges, each spanned by a tree.
    std::vector<GraphEdge> chosen;
    UnionFind groups(n);
    for (const GraphEdge& e : edges) {
        if (terminal[e[0]] && terminal[e[1]] && groups.join(e[0], e[1]))
            chosen.push_back(sorted(e[0], e[1]));
    }

    // 2. Voronoi regions of the groups by one breadth-first search from every terminal.
    std::vector<Index> group(n, -1), parent(n, -1), distance(n, -1);
    std::queue<Index> queue;
    for (Index v = 0; v < n; ++v) {
        if (terminal[v]) {
            group[v] = groups.find(v);
            distance[v] = 0;
            queue.push(v);
        }
    }
    while (!queue.empty()) {
        const Index v = queue.front();
        queue.pop();
        for (Index i = graph.begin[v]; i < graph.begin[v + 1]; ++i) {
            const Index w = graph.neighbours[i];
            if (distance[w] >= 0) continue;
            distance[w] = distance[v] + 1;
            group[w] = group[v];
            parent[w] = v;
            queue.push(w);
        }
    }

    // 3. Minimum spanning tree over the groups: each graph edge between two regions is a
    //    candidate path of length d(u) + 1 + d(v) (Kruskal, ties broken by the edge order).
    struct Candidate {
        Index length;
        std::size_t edge;
    };
    std::vector<Candidate> candidates;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const Index u = edges[i][0], v = edges[i][1];
        if (group[u] >= 0 && group[v] >= 0 && group[u] != group[v]) {
            candidates.push_back({distance[u] + 1 + distance[v], i});
        }
    }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.length < b.length; });
    UnionFind joined(n);
    for (const Candidate& c : candidates) {
        const Index u = edges[c.edge][0], v = edges[c.edge][1];
        if (!joined.join(group[u], group[v])) continue;
        chosen.push_back(sorted(u, v));
        for (Index w : {u, v}) {
            for (Index x = w; parent[x] >= 0; x = parent[x]) chosen.push_back(sorted(x, parent[x]));
        }
    }
    std::sort(chosen.begin(), chosen.end());
    chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());

    // 4. A spanning forest of the union, then prune leaves that are not terminals.
    UnionFind forest(n);
    std::vector<GraphEdge> tree;
    for (const GraphEdge& e : chosen) {
        if (forest.join(e[0], e[1])) tree.push_back(e);
    }
    const Adjacency tree_graph(n, tree);
    std::vector<Index> degree(n, 0);
    for (const GraphEdge& e : tree) ++degree[e[0]], ++degree[e[1]];
    std::vector<unsigned char> gone(n, 0);
    std::vector<Index> leaves;
    for (Index v = 0; v < n; ++v) {
        if (degree[v] == 1 && !terminal[v]) leaves.push_back(v);
    }
    while (!leaves.empty()) {
        const Index v = leaves.back();
        leaves.pop_back();
        gone[v] = 1;
        for (Index i = tree_graph.begin[v]; i < tree_graph.begin[v + 1]; ++i) {
            const Index w = tree_graph.neighbours[i];
            if (gone[w]) continue;
            if (--degree[w] == 1 && !terminal[w]) leaves.push_back(w);
        }
    }
    std::vector<GraphEdge> result;
    for (const GraphEdge& e : tree) {
        if (!gone[e[0]] && !gone[e[1]]) result.push_back(e);
    }
    return result;
}

}  // namespace sa
