#pragma once
// Vertex positions from per-simplex linear parts, by the least squares of Eq. 6:
//     minimize  sum_i sum_{edges (a, b) of s_i} |A_i (u_a - u_b) - (x_a - x_b)|^2
// with u the rest corners in s_i's frame, over the free vertices; fixed vertices (handles) keep
// their given positions. Every edge of every simplex contributes, which in 2D is exactly Eq. 6's
// sum over edges and their two adjacent simplices. The normal equations (a graph Laplacian, the
// same for every coordinate and for every set of A_i) are factored once (LinearSolverType::kAuto:
// Eigen's LDLT for small meshes, whose solves the supernodal factor's per-supernode BLAS calls
// made 3x slower, CHOLMOD supernodal for large ones); each recover() is a right-hand side and
// triangular solves.
// Each connected component needs at least one fixed vertex; vertices in no simplex keep their
// given positions.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "geometry/mesh/rest_frames.h"
#include "optim/linear_solver.h"

namespace sa {

template <int D>
class VertexRecovery {
  public:
    /// Factors the Laplacian of `mesh` with the `fixed` vertices removed. Throws
    /// InvalidArgumentError when a connected component has no fixed vertex.
    VertexRecovery(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                   std::vector<unsigned char> fixed);

    /// `positions` (#V x D) gives the fixed vertices' positions (other rows are copied for unused
    /// vertices and ignored otherwise). Returns all positions.
    Eigen::MatrixXd recover(const std::vector<Mat<D>>& A, const Eigen::MatrixXd& positions) const;

    const std::vector<unsigned char>& fixed() const { return fixed_; }

  private:
    const SimplicialMesh& mesh_;
    const RestFrames<D>& frames_;
    std::vector<unsigned char> fixed_;
    std::vector<Index> free_index_;
    Index num_free_ = 0;
    std::unique_ptr<LinearSolver> solver_;
};

/// One-off recovery: VertexRecovery(mesh, frames, fixed).recover(A, positions).
template <int D>
Eigen::MatrixXd recover_vertices(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                                 const std::vector<Mat<D>>& A, const Eigen::MatrixXd& positions,
                                 const std::vector<unsigned char>& fixed);

}  // namespace sa
