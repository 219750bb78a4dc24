#pragma once
// A genus-0 triangle surface with several boundary loops (an annulus, a disk with holes) made a
// disk for the starts of a planar parameterization: every loop but the outer one (the longest,
// measured on the surface) is closed by a fan of triangles from a new vertex at the loop's
// centroid, oriented like the surface. A Tutte map of the filled disk is valid, and so is its
// restriction to the input's triangles; LSCM and the harmonic map see the holes as surface.

#include <vector>

#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/simplicial_mesh.h"

namespace sa {

struct FilledHoles {
    /// The input's vertices and triangles first, in their order, then one vertex per filled hole
    /// and its fan.
    SimplicialMesh mesh;
    Index holes = 0;  ///< loops filled (all but the outer one)
};

/// `mesh`: triangles (in space or in the plane) with `topology`, every vertex used, a manifold
/// boundary of at least one loop (require_planar_surface in boundary_loops.h checks all of it).
FilledHoles fill_inner_holes(const SimplicialMesh& mesh, const MeshTopology& topology);

}  // namespace sa
