#pragma once
// The boundary-angle barrier E_theta of section 5.1 ("Locally injective mapping"): for a boundary
// vertex v of a triangle mesh mapped to the plane,
//     E_theta(v) = 1 / (2 pi - theta_v),   theta_v = sum of the angles at v of its triangles'
//     images,
// +inf when theta_v >= 2 pi. With every triangle positively oriented, theta_v < 2 pi at every
// boundary vertex makes the map locally injective on the boundary (Lipman 2014).
//
// The K triangles around v form a fan, from the boundary edge leaving v to the one entering it;
// the angle of triangle k is arg(b_k) - arg(a_k) (atan2 of cross and dot), a_k and b_k the images
// of its two edges at v. Both edges are linear in the variables, so closed-form derivatives follow
// from those of arg(u):  d arg / du = (-u_y, u_x) / |u|^2,
//     d^2 arg / du^2 = [2 u_x u_y, u_y^2 - u_x^2; u_y^2 - u_x^2, -2 u_x u_y] / |u|^4.
//
//   BoundaryAngleEnergy        variables: vec(A_k) of the K triangles (4 K), each triangle's
//                              two edges at v given in its rest frame (r-SA and f-SA)
//   BoundaryAngleVertexEnergy  variables: the positions of v and of its K + 1 fan neighbours in
//                              order (2 K + 4) (the vertex stage)
// Both are of run-time arity (optim/dynamic_element_energy.h): one term holds the fans of every
// size, each element's Hessian dense.

#include <vector>

#include "optim/dynamic_element_energy.h"
#include "optim/types.h"

namespace sa {

/// E_theta of one boundary vertex from its angle sum: 1 / (2 pi - theta), +inf from 2 pi on.
inline double boundary_angle_barrier(double theta) {
    return theta < 2.0 * M_PI ? 1.0 / (2.0 * M_PI - theta) : kInfinity;
}

struct BoundaryAngleEnergy {
    static constexpr int arity = kDynamicArity;
    /// Per element (boundary vertex), per fan triangle: its edges at v (columns), rest frame.
    std::vector<std::vector<Mat<2>>> edges;

    Index num_elements() const { return static_cast<Index>(edges.size()); }
    int element_arity(Index e) const { return 4 * static_cast<int>(edges[e].size()); }
    double value(Index e, ConstVectorRef x) const;
    double value_gradient_hessian(Index e, ConstVectorRef x, VectorRef g, MatrixRef h) const;
};

struct BoundaryAngleVertexEnergy {
    static constexpr int arity = kDynamicArity;

    double value(Index e, ConstVectorRef x) const;
    double value_gradient_hessian(Index e, ConstVectorRef x, VectorRef g, MatrixRef h) const;
};

}  // namespace sa
