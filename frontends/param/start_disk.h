#pragma once
// The disk a parameterization's starts (LSCM, Tutte, harmonic) are computed on: the surface's
// triangles on the vertices they use (a mesh file may hold others, which take no part in the
// map), with every boundary loop but the outer one filled (hole_filling.h). A start on it becomes
// a map of the surface by to_surface().

#include <string>
#include <vector>

#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/simplicial_mesh.h"

namespace sa {

struct StartDisk {
    SimplicialMesh mesh;    ///< a topological disk
    MeshTopology topology;  ///< of `mesh`
    /// Per vertex of `mesh`: its vertex of the surface; -1 for the centre of a filled hole.
    std::vector<Index> surface_vertex;
    Index surface_vertices = 0;  ///< #V of the surface
    Index filled_holes = 0;
    Index unused_vertices = 0;  ///< vertices of the surface that belong to no triangle

    /// `uv` (#V of `mesh` x 2) as a map of the surface (#V x 2); a vertex of no triangle is put at
    /// the centroid of the others.
    Eigen::MatrixXd to_surface(const Eigen::MatrixXd& uv) const;
};

/// `surface`: triangles that require_planar_surface (boundary_loops.h) accepts, with `topology`.
StartDisk start_disk(const SimplicialMesh& surface, const MeshTopology& topology,
                     const std::string& source);

}  // namespace sa
