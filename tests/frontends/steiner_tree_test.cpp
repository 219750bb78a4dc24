#include <gtest/gtest.h>

#include <numeric>
#include <random>
#include <set>

#include "frontends/simplex_assembly/steiner_tree.h"

namespace sa {
namespace {

// True when `tree` is a forest without cycles whose edges connect all terminals that the graph
// connects, i.e. one tree when the graph is connected.
bool connects_as_tree(Index n, const std::vector<GraphEdge>& tree,
                      const std::vector<Index>& terminals) {
    std::vector<Index> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](Index v) {
        while (parent[v] != v) v = parent[v];
        return v;
    };
    for (const GraphEdge& e : tree) {
        const Index a = find(e[0]), b = find(e[1]);
        if (a == b) return false;  // a cycle
        parent[a] = b;
    }
    for (Index t : terminals) {
        if (find(t) != find(terminals[0])) return false;
    }
    return true;
}

// The fewest edges of a tree connecting all terminals, by enumerating edge subsets.
int brute_force_steiner(Index n, const std::vector<GraphEdge>& edges,
                        const std::vector<Index>& terminals) {
    int best = 1 << 30;
    for (unsigned mask = 0; mask < (1u << edges.size()); ++mask) {
        std::vector<GraphEdge> subset;
        for (std::size_t i = 0; i < edges.size(); ++i) {
            if (mask & (1u << i)) subset.push_back(edges[i]);
        }
        if (int(subset.size()) < best && connects_as_tree(n, subset, terminals))
            best = int(subset.size());
    }
    return best;
}

std::vector<GraphEdge> random_connected_graph(std::mt19937& rng, Index n, int extra) {
    std::vector<GraphEdge> edges;
    std::set<GraphEdge> seen;
    for (Index v = 1; v < n; ++v) {  // a random spanning tree first
        const Index u = std::uniform_int_distribution<Index>(0, v - 1)(rng);
        edges.push_back({u, v});
        seen.insert({u, v});
    }
    for (int k = 0; k < extra; ++k) {
        Index a = std::uniform_int_distribution<Index>(0, n - 1)(rng);
        Index b = std::uniform_int_distribution<Index>(0, n - 1)(rng);
        if (a == b) continue;
        GraphEdge e{std::min(a, b), std::max(a, b)};
        if (seen.insert(e).second) edges.push_back(e);
    }
    return edges;
}

TEST(SteinerTree, ContainsEveryTerminalAndMatchesBruteForceOnTinyGraphs) {
    std::mt19937 rng(17);
    int matched = 0, cases = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const Index n = std::uniform_int_distribution<Index>(4, 8)(rng);
        const auto edges =
            random_connected_graph(rng, n, std::uniform_int_distribution<int>(0, 5)(rng));
        std::vector<Index> vertices(n);
        std::iota(vertices.begin(), vertices.end(), 0);
        std::shuffle(vertices.begin(), vertices.end(), rng);
        const int k = std::uniform_int_distribution<int>(2, std::min<int>(n, 4))(rng);
        const std::vector<Index> terminals(vertices.begin(), vertices.begin() + k);
        const auto tree = approximate_steiner_tree(n, edges, terminals);
        ASSERT_TRUE(connects_as_tree(n, tree, terminals)) << "trial " << trial;
        const int optimum = brute_force_steiner(n, edges, terminals);
        EXPECT_LE(int(tree.size()), 2 * optimum) << "trial " << trial;  // the 2-approximation bound
        ++cases;
        matched += int(tree.size()) == optimum;
    }
    // Mehlhorn's approximation with pruning is optimal on nearly all tiny graphs.
    EXPECT_GE(matched, cases * 95 / 100) << matched << " of " << cases << " optimal";
}

TEST(SteinerTree, IsExactOnTreesAndForTwoTerminals) {
    std::mt19937 rng(5);
    for (int trial = 0; trial < 50; ++trial) {
        const Index n = 30;
        const auto tree_graph = random_connected_graph(rng, n, 0);  // the graph is a tree
        std::vector<Index> terminals = {Index(trial % n), Index((trial * 7 + 3) % n),
                                        Index((trial * 13 + 5) % n)};
        const auto tree = approximate_steiner_tree(n, tree_graph, terminals);
        // In a tree the Steiner tree is the union of the paths between terminals: every leaf of
        // the result is a terminal, and it connects them.
        EXPECT_TRUE(connects_as_tree(n, tree, terminals));
        std::vector<int> degree(n, 0);
        for (const auto& e : tree) ++degree[e[0]], ++degree[e[1]];
        for (Index v = 0; v < n; ++v) {
            if (degree[v] == 1) {
                EXPECT_TRUE(std::find(terminals.begin(), terminals.end(), v) != terminals.end());
            }
        }
    }
    // Two terminals at the ends of a 6-cycle with a chord: the shortest path.
    const std::vector<GraphEdge> cycle = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {0, 5}, {1, 4}};
    EXPECT_EQ(approximate_steiner_tree(6, cycle, {0, 3}).size(), 3u);
}

TEST(SteinerTree, ConnectedTerminalsNeedNoOtherVertex) {
    // A boundary loop of handles: the tree is a spanning path of the loop.
    std::vector<GraphEdge> loop;
    std::vector<Index> terminals;
    for (Index v = 0; v < 10; ++v) {
        loop.push_back({std::min(v, (v + 1) % 10), std::max(v, (v + 1) % 10)});
        terminals.push_back(v);
    }
    loop.push_back({0, 10});  // a vertex off the loop
    const auto tree = approximate_steiner_tree(11, loop, terminals);
    EXPECT_EQ(tree.size(), 9u);
    EXPECT_TRUE(connects_as_tree(11, tree, terminals));
}

}  // namespace
}  // namespace sa
