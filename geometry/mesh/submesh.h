#pragma once
// Submeshes for the speed-up of section 4.4: rings of simplices around seeds, their connected
// regions, and a region extracted as a mesh of its own with its boundary vertices marked.
//
// Rings are counted over shared vertices: ring 1 of a set adds every simplex that shares a vertex
// with it. Two regions that share a vertex are one region (merge_touching_regions), so regions
// solved side by side never move a vertex the other one uses.

#include <vector>

#include "geometry/mesh/mesh_topology.h"

namespace sa {

/// The seeds plus `rings` rings of simplices around them (sorted).
std::vector<Index> grow_rings(const SimplicialMesh& mesh, const MeshTopology& topology,
                              const std::vector<Index>& seeds, int rings);

/// `region` (sorted) plus the parts of the mesh it encloses: the components of the rest of the
/// mesh (connected over shared facets) that hold no boundary facet of the mesh; in a connected
/// part of the mesh without boundary, every component of the rest but its largest. Sorted.
///
/// A triangle region with a hole cannot be solved alone: the linear parts can agree on every
/// shared edge and still fail to integrate to vertex positions around the hole (a period), so that
/// the recovered map folds although every simplex was assembled.
std::vector<Index> fill_enclosed(const MeshTopology& topology, const std::vector<Index>& region);

/// Splits a set of simplices into groups connected through shared vertices (each sorted; groups
/// ordered by their smallest simplex).
std::vector<std::vector<Index>> vertex_connected_regions(const SimplicialMesh& mesh,
                                                         const MeshTopology& topology,
                                                         const std::vector<Index>& simplices);

/// A region of a mesh as a mesh of its own.
struct Submesh {
    std::vector<Index> simplices;  ///< in the whole mesh
    std::vector<Index> vertices;   ///< in the whole mesh; local vertex i is vertices[i]
    SimplicialMesh mesh;           ///< local indices, rest positions copied
    /// Local vertices that also belong to a simplex outside the region: they cannot move.
    std::vector<unsigned char> on_region_boundary;
};

Submesh extract_submesh(const SimplicialMesh& mesh, const MeshTopology& topology,
                        const std::vector<Index>& simplices);

/// Colours of a graph (greedy in vertex order, smallest free colour): no two adjacent nodes share
/// one. `adjacency[i]` lists the neighbours of node i.
std::vector<int> greedy_coloring(const std::vector<std::vector<Index>>& adjacency);

}  // namespace sa
