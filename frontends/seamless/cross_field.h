#pragma once
// Cross fields on triangle surfaces in space: the input of seamless parameterization (the paper's
// section 4.5 and "Global seamless parameterizations" in 5.2).
//
// A cross is four unit tangent directions at right angles; per face we store one of them, a unit
// vector in the face's plane (#F x 3). In the face's local frame (e1 = the normalized edge
// v0 -> v1, e2 = n x e1) a direction is a complex number u of modulus 1 and the cross is u^4.
//
// Transport across an interior edge e shared by faces f and g (the Levi-Civita connection of the
// flattened pair): a direction keeps its angle to e, so u_g = r_fg u_f with
// r_fg = conj(c_f(e)) c_g(e), c_f(e) the unit complex coordinate of e in f's frame.
//
//   smoothest_cross_field   minimizes sum_e |z_g - r_fg^4 z_f|^2 over z = u^4 (Knöppel et al.
//                           2013, "Globally optimal direction fields", with unit edge weights):
//                           with a boundary, z is fixed on boundary faces to the boundary edge's
//                           direction (a boundary-aligned field; one linear solve); on a closed
//                           surface, the eigenvector of the connection Laplacian with the smallest
//                           eigenvalue relative to the face areas (inverse iteration, CHOLMOD).
//                           Faces may also be constrained to given directions (as libigl's
//                           constrained fields: the vectors a user placed).
//   cross_field_singularities   per vertex, index = (K_v + sum of the field's turning across the
//                           edges around v, each reduced to (-pi/4, pi/4]) / 2 pi, K_v the angle
//                           defect (2 pi - the angle sum; pi - the angle sum at a boundary
//                           vertex, whose turning runs along its open fan). Indices are multiples
//                           of 1/4; over a closed surface they sum to its Euler characteristic
//                           (Poincaré-Hopf).

#include <Eigen/Core>
#include <vector>

#include "geometry/mesh/mesh_topology.h"

namespace sa {

/// A face whose cross is prescribed: one of its directions (tangent to the face up to a normal
/// component, which is dropped; need not be unit).
struct CrossFieldConstraint {
    Index face;
    Eigen::Vector3d direction;
};

/// #F x 3: one unit tangent vector per face, representing its cross. Constrained faces are fixed
/// to their given direction (then, like a boundary, they make the problem one linear solve) and
/// take precedence over the boundary alignment. Throws InputError for a constraint out of range
/// or without a tangent component.
Eigen::MatrixXd smoothest_cross_field(const SimplicialMesh& mesh, const MeshTopology& topology,
                                      const std::vector<CrossFieldConstraint>& constraints = {});

struct Singularity {
    Index vertex;
    double index;  ///< a nonzero multiple of 1/4
};

/// The vertices where the cross field `directions` (#F x 3) turns (index != 0). Throws
/// InputError when a direction is not tangent to its face or vanishes.
std::vector<Singularity> cross_field_singularities(const SimplicialMesh& mesh,
                                                   const MeshTopology& topology,
                                                   const Eigen::MatrixXd& directions);

}  // namespace sa
