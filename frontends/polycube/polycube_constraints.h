#pragma once
// The linear constraints of a PolyCube map (the paper's 5.3), as rows of
// LinearConstraintEnergy (energies/linear_constraint_energy.h), in the two variable layouts of
// Simplex Assembly:
//
//   A-form (assembly stage): variables vec(A_i) (9, column-major) of the tetrahedron that owns a
//       boundary facet, then, for sliding, its translation T_i (3); a rest point u of the
//       tetrahedron (in its rest frame) maps to A_i u + T_i.
//   vertex form (vertex stage): the positions of the vertices, 3 each.
//
// Planarity: a boundary facet labelled with axis a must map into a plane orthogonal to a: for two
// of its edges e_1, e_2 (rest, normalized to unit length as in Eq. 7),
//     a^T A_i e_k = 0,  k = 1, 2          (A-form: 2 rows on vec(A_i))
//     a^T (x_{k} - x_0) / |e_k| = 0       (vertex form: 2 rows on the facet's 3 vertices, 9)
// The third edge is their difference. With edge assembly (Eq. 7) the images of a chart's facets
// then lie in one plane orthogonal to a.
//
// Sliding: a boundary vertex stays on its chart's plane a^T y = c (one chart), on the line where
// two charts meet (two rows), or at a corner of three (three rows), c the planes' coordinates
// (fixed, e.g. from the cube-cover start):
//     a_k^T (A_i u + T_i) = c_k            (A-form: R rows on (vec(A_i), T_i), 12)
//     a_k^T y_v = c_k                      (vertex form: R rows on the vertex, 3)

#include <array>

#include "energies/linear_constraint_energy.h"

namespace sa {

/// Planarity in A-form: `edges` holds two rest edges of the facet (columns, in the tetrahedron's
/// rest frame), normalized here. Throws InvalidArgumentError on an axis outside 0..2 or a
/// zero-length edge.
LinearConstraintRows<9, 2> planarity_rows(int axis, const Eigen::Matrix<double, 3, 2>& edges);

/// Planarity in vertex form over the facet's vertices (x_0, x_1, x_2), each 3 variables, with the
/// rest lengths of the edges x_1 - x_0 and x_2 - x_0.
LinearConstraintRows<9, 2> planarity_vertex_rows(int axis, const std::array<double, 2>& lengths);

/// Sliding in A-form on R planes (R = 1, 2 or 3 distinct axes) of coordinates `coordinates`, for
/// the rest point `rest_point` of the tetrahedron (its rest frame).
template <int R>
LinearConstraintRows<12, R> sliding_rows(const Eigen::Vector3d& rest_point,
                                         const std::array<int, R>& axes,
                                         const std::array<double, R>& coordinates);

/// Sliding in vertex form: R rows on one vertex position.
template <int R>
LinearConstraintRows<3, R> sliding_vertex_rows(const std::array<int, R>& axes,
                                               const std::array<double, R>& coordinates);

}  // namespace sa
