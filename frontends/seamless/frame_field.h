#pragma once
// Frame fields on triangle surfaces as per-face 2 x 2 matrices, the variables of Eq. 11 (the
// paper's 4.5 and "Global seamless parameterizations" in 5.2).
//
// The mesh is a triangle mesh in space (3 coordinates per vertex; a planar mesh gets z = 0).
// A frame is two tangent vectors (u, v) per face; in the face's rest frame (rest_frames.h: x along
// the first edge, y = n x x) they are the rows of A: A = [u^T; v^T], the Jacobian that the
// parameterization's (u, v) coordinates should have there (grad u along the first vector, grad v
// along the second). A cross field (one direction d per face) is the frame (d, n x d).
//
// Edge curl (Eq. 11): for an interior edge e between faces f = simplex[0] and g = simplex[1],
// with e_f and e_g the edge's unit vector in each face's frame and k the matching of the edge
// (cut_graph.h),
//     curl_e = |A_f e_f - Rot(k quarter turns) A_g e_g|.
// It vanishes for all edges exactly when the field is the Jacobian of a seamless map whose charts
// differ across each edge by Rot(-k quarter turns) (seamless_poisson.h) and a translation.

#include <Eigen/Core>
#include <vector>

#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/rest_frames.h"

namespace sa {

/// One matrix per face from per-face vectors in space (#F x 3 each): rows u and v projected onto
/// the face. `v` empty (0 rows): a cross field, v = n x u. A face whose frame is left-handed gets
/// -v (a frame's vectors are defined up to sign). Throws InputError naming the face when u
/// vanishes on the face or u and v are parallel there.
std::vector<Mat<2>> frame_matrices(const RestFrames<2>& frames, const Eigen::MatrixXd& u,
                                   const Eigen::MatrixXd& v = {});

/// The inverse of frame_matrices: the rows of each A_f as vectors in space, #F x 3 each.
std::pair<Eigen::MatrixXd, Eigen::MatrixXd> frame_vectors(const RestFrames<2>& frames,
                                                          const std::vector<Mat<2>>& matrices);

/// #F x 3: per face the first direction of the closest rotation to A_f, in space: the cross
/// that the frame field carries (for singularities and matchings, cross_field.h, cut_graph.h).
Eigen::MatrixXd frame_cross_directions(const RestFrames<2>& frames,
                                       const std::vector<Mat<2>>& matrices);

/// The mean length of the rows of the matrices: the field's size.
double mean_row_norm(const std::vector<Mat<2>>& matrices);

/// The rotation by k quarter turns (counter-clockwise).
Mat<2> quarter_turns(int k);

/// curl_e per interior facet (topology.interior_facets order), in the units of A.
Eigen::VectorXd edge_curl(const SimplicialMesh& mesh, const MeshTopology& topology,
                          const RestFrames<2>& frames, const std::vector<Mat<2>>& matrices,
                          const std::vector<int>& matching);

/// The unit vectors of interior facet i's edge in its two faces' frames (e_f, e_g above).
std::pair<Vec<2>, Vec<2>> facet_edge_in_frames(const SimplicialMesh& mesh,
                                               const RestFrames<2>& frames,
                                               const InteriorFacet& facet);

}  // namespace sa
