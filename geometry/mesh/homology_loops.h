#pragma once
// Closed loops of mesh edges that generate the first homology of a triangulated surface: the
// loops around which a map's edge vectors, once every triangle closes, may still fail to close
// (a handle, a hole). r-SA imposes them (frontends/simplex_assembly/detail/assembly_problem.h).
//
// Tree-cotree (Eppstein 2003): a breadth-first spanning tree of the vertex graph, then a spanning
// forest of the dual graph over the edges not in that tree, in which every boundary edge leads
// to one extra node standing for all the boundary. Each edge in neither tree closes one loop
// through the primal tree. Peeling the dual forest from that extra node writes every other
// non-tree edge's loop as a sum of these loops and triangle boundaries, so they generate
// H1 over the rationals: 2g + b - 1 loops for a connected surface of genus g with b > 0 boundary
// loops (none for a disk), 2g for a closed one. Edges in more than two triangles are tolerated
// (two of them are joined in the dual; the loops then still generate, some of them redundant).
//
// The boundary surface of a solid in space carries its loops too: over the rationals the solid's
// H1 is the image of its boundary's (Alexander duality), so the boundary's loops, half of them
// spanning a surface inside the solid, generate the solid's.

#include <array>
#include <vector>

#include "optim/types.h"

namespace sa {

/// Each loop as its vertices v_0, ..., v_{n-1} (n >= 3), the edges v_k v_{k+1} and v_{n-1} v_0
/// being edges of the triangles. Deterministic for given triangles; vertices in no triangle are
/// ignored.
std::vector<std::vector<Index>> homology_loops(Index num_vertices,
                                               const std::vector<std::array<Index, 3>>& triangles);

}  // namespace sa
