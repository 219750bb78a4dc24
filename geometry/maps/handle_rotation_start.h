#pragma once
// A start for ARAP deformation with handles (geometry/maps/arap_deformation.h) that already carries
// the handles' rotations through the mesh: large rotations (a bar twisted by 180 degrees, bent
// by 90) are what local/global iterations spread slowly, from the rest shape with the handles
// moved, and where they can settle in a folded local minimum (the twist's: 6 tetrahedra folded
// around the axis).
//
//  1. The handles split into groups: connected by mesh edges between handles. Each group whose
//     rest positions determine a rotation (at least two distinct points in 2D, three not on a
//     line in 3D) gets its best rigid fit, the rotation R_g of the Kabsch/Horn problem
//     (geometry/maps/rotation_fit.h of sum_k (t_k - t_bar)(p_k - p_bar)^T, p rest, t target).
//  2. A rotation field: the unit quaternions (unit complex numbers in 2D) of the R_g, signs
//     chosen towards the largest group's, interpolated harmonically (the graph Laplacian of the
//     global step, with the groups' vertices fixed) and normalized per simplex. One group gives
//     its rotation everywhere, none the identity. A connected part without such a group takes
//     the fit of all its handles.
//  3. The global step (Eq. 6, geometry/maps/vertex_recovery.h) with those rotations and the handles
//     at their targets: a bar twisted by its end slabs starts twisted along its length.
//
// Interpolating rotations through their quaternions takes the shorter way round: a group turned
// by more than half a turn from the reference starts turned the other way, as the targets alone
// cannot tell. A strip bent by 270 degrees then starts bent back by 90 and ends at a higher Q
// than from the rest shape (1.14 against 1.05, tests/geometry/handle_rotation_start_test.cpp):
// arap_deformation() compares the two starts' Q, but not where they lead.

#include <Eigen/Core>

#include "geometry/maps/vertex_recovery.h"
#include "geometry/mesh/rest_frames.h"

namespace sa {

struct HandleRotationStart {
    Eigen::MatrixXd positions;  ///< #V x D, the handles at their targets
    int groups = 0;             ///< handle groups
    int rotation_groups = 0;    ///< of them, those that determine a rotation
};

/// `start` (#V x D) has the handle targets in the rows of recovery.fixed(); `mesh.vertices` is the
/// rest shape (simplices of dimension D in D-space).
template <int D>
HandleRotationStart handle_rotation_start(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                                          const VertexRecovery<D>& recovery,
                                          const Eigen::MatrixXd& start);

}  // namespace sa
