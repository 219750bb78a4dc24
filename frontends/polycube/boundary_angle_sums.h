#pragma once
// The boundary angle sums of a tetrahedral map (the quantities the 3D barriers of
// frontends/polycube/tet_angle_barriers.h keep below their limits), from vertex positions:
//   theta_e = sum of the dihedral angles at boundary edge e of the tetrahedra around it,
//   theta_v = sum of the solid angles at boundary vertex v of the tetrahedra around it,
// each angle signed against its tetrahedron's rest orientation. A map whose tetrahedra all keep
// their orientation is locally injective at the boundary when every theta_e < 2 pi and every
// theta_v < 4 pi. An undefined angle (a vanishing edge or face) makes the sum +inf.

#include <Eigen/Core>
#include <vector>

#include "frontends/polycube/tet_boundary_fans.h"

namespace sa {

/// theta_e of each fan at `positions` (#V x 3).
std::vector<double> dihedral_angle_sums(const std::vector<BoundaryEdgeFan>& fans,
                                        const Eigen::MatrixXd& positions);

/// theta_v of each star at `positions` (#V x 3).
std::vector<double> solid_angle_sums(const std::vector<BoundaryVertexStar>& stars,
                                     const Eigen::MatrixXd& positions);

}  // namespace sa
