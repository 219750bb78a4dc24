#pragma once
// An approximate minimum Steiner tree of an unweighted graph: a tree with few edges that
// connects every terminal (section 4.3, where the terminals are the handles and the tree carries
// the only translation variables of r-SA).
//
// As in the paper: terminals connected to each other form groups, each spanned by a tree of
// terminal-terminal edges; the groups are then joined along shortest paths chosen by a minimum
// spanning tree over group distances. Group distances come from one multi-source breadth-first
// search (Mehlhorn 1988) rather than one search per pair of groups: the same 2-approximation,
// in O(E log E) for any number of groups. Finally the union is reduced to a spanning tree and
// leaves that are not terminals are pruned (Kou, Markowsky and Berman 1981).
// Terminals in different connected components of the graph give a forest, one tree each.

#include <array>
#include <vector>

#include "optim/types.h"

namespace sa {

using GraphEdge = std::array<Index, 2>;

/// The tree's edges (each sorted), deterministic for given inputs.
std::vector<GraphEdge> approximate_steiner_tree(Index num_vertices,
                                                const std::vector<GraphEdge>& edges,
                                                const std::vector<Index>& terminals);

}  // namespace sa
