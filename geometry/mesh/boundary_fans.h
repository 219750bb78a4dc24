#pragma once
// The fan of triangles around each boundary vertex of a disk-like triangle mesh, in order, and
// the angle sums theta_v of a planar map at those vertices (section 5.1: a map is locally
// injective on the boundary when every triangle keeps its orientation and theta_v < 2 pi).

#include <Eigen/Core>
#include <vector>

#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/rest_frames.h"

namespace sa {

struct BoundaryFan {
    Index vertex = -1;
    /// Triangle k has corners (vertex, neighbours[k], neighbours[k + 1]) in its own order; the
    /// fan runs from the boundary edge leaving `vertex` to the one entering it.
    std::vector<Index> triangles;
    std::vector<Index> neighbours;  ///< triangles.size() + 1 vertices
};

/// One fan per boundary vertex of a manifold triangle mesh (in boundary-loop order).
std::vector<BoundaryFan> boundary_fans(const SimplicialMesh& mesh, const MeshTopology& topology);

/// Triangle k of `fan`: its edges from the fan's vertex to neighbours[k] and neighbours[k + 1]
/// (columns), in the triangle's rest frame.
Mat<2> fan_edges(const SimplicialMesh& mesh, const RestFrames<2>& frames, const BoundaryFan& fan,
                 std::size_t k);

/// theta_v of each fan for planar positions `uv` (#V x 2): the sum of signed corner angles.
std::vector<double> boundary_angle_sums(const std::vector<BoundaryFan>& fans,
                                        const Eigen::MatrixXd& uv);

/// How many fans have theta_v >= 2 pi.
Index count_boundary_violations(const std::vector<BoundaryFan>& fans, const Eigen::MatrixXd& uv);

}  // namespace sa
