#pragma once
// Vertex positions from per-simplex linear parts, by the least squares of Eq. 6:
//     minimize  sum_i sum_{edges (a, b) of s_i} |A_i (u_a - u_b) - (x_a - x_b)|^2
// with u the rest corners in s_i's frame, over the free vertices; fixed vertices (handles) keep
// their given positions. Every edge of every simplex contributes, which in 2D is exactly Eq. 6's
// sum over edges and their two adjacent simplices. The normal equations (a graph Laplacian,
// the same for every coordinate) are factored once with CHOLMOD and solved per coordinate.
// Each connected component needs at least one fixed vertex; vertices in no simplex keep their
// given positions.

#include <Eigen/Core>
#include <vector>

#include "geometry/rest_frames.h"

namespace sa {

/// `positions` (#V x D) gives the fixed vertices' positions (other rows are ignored except for
/// unused vertices, which are copied); `fixed` flags them. Throws InvalidArgumentError when a
/// component has no fixed vertex.
template <int D>
Eigen::MatrixXd recover_vertices(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                                 const std::vector<Mat<D>>& A, const Eigen::MatrixXd& positions,
                                 const std::vector<unsigned char>& fixed);

}  // namespace sa
