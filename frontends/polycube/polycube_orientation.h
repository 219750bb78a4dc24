#pragma once
// The orientation in which to label a tetrahedral mesh's boundary by closest axis, for a PolyCube
// map with computed labels. Closest-axis labels depend on how the input happens to be turned: a
// box turned by 45 degrees about one axis has two faces whose normals lie halfway between two
// axes, and its labels are noise there. As Huang et al. ("l1-based construction of polycube maps
// from complex shapes", 2014) do, the rotation R is chosen to minimize the l1 norm of the
// boundary's area vectors,
//     E(R) = sum_b |R a_b|_1 / sum_b |a_b|_2          (a_b: outward area vector of triangle b),
// which is 1 when every triangle faces an axis and up to sqrt(3) when it faces a diagonal. The
// PolyCube map does not see R otherwise: its energies (conformal distortion, angle sums) are
// invariant under rotations of the rest shape.
//
// The search: the identity, a 10-degree grid of Euler angles that meets every rotation up to
// the cube's 24 rotations (which E cannot tell apart), then a pattern search (small rotations
// about x, y and z, halving the step) from the best few. A candidate replaces the best only when
// it lowers E by more than rounding (1e-9 relative), so that an axis-aligned input keeps R = I.
#include <Eigen/Core>

#include "geometry/mesh/tet_boundary.h"

namespace sa {

struct PolycubeOrientation {
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< R: label and map R x
    double energy_identity = 0.0;                            ///< E(I), 1 .. sqrt(3)
    double energy = 0.0;                                     ///< E(R)
    double angle_degrees = 0.0;                              ///< R's angle about its axis
    int evaluations = 0;                                     ///< of E
};

/// The rotation minimizing E above for the boundary of a mesh with vertex `positions` (#V x 3).
/// Throws InvalidArgumentError when the boundary has no area.
PolycubeOrientation polycube_orientation(const TetBoundary& boundary,
                                         const Eigen::MatrixXd& positions);

/// E(R) of the outward area vectors `area_vectors` (#B x 3).
double l1_alignment(const Eigen::MatrixXd& area_vectors, const Eigen::Matrix3d& rotation);

}  // namespace sa
