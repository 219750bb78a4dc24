#include "geometry/maps/vertex_recovery.h"

#include <Eigen/Sparse>
#include <string>

#include "geometry/detail/union_find.h"
#include "optim/errors.h"

namespace sa {

template <int D>
VertexRecovery<D>::VertexRecovery(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                                  std::vector<unsigned char> fixed)
    : mesh_(mesh), frames_(frames), fixed_(std::move(fixed)) {
    const Index nv = mesh.num_vertices();
    std::vector<unsigned char> used(nv, 0);
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        for (int k = 0; k <= D; ++k) used[mesh.simplices(s, k)] = 1;
    }
    free_index_.assign(nv, -1);
    for (Index v = 0; v < nv; ++v) {
        if (used[v] && !fixed_[v]) free_index_[v] = num_free_++;
    }
    if (num_free_ == 0) return;
    // Each connected part of the mesh needs a fixed vertex, or the system is singular: checked on
    // the graph itself, since a factorization of a singular system need not fail in rounding.
    UnionFind parts(nv);
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        for (int k = 1; k <= D; ++k) parts.join(mesh.simplices(s, k), mesh.simplices(s, 0));
    }
    std::vector<unsigned char> anchored(nv, 0);
    for (Index v = 0; v < nv; ++v) {
        if (used[v] && fixed_[v]) anchored[parts.find(v)] = 1;
    }
    for (Index v = 0; v < nv; ++v) {
        if (used[v] && !anchored[parts.find(v)]) {
            throw InvalidArgumentError(
                "vertex recovery: the system is singular: a connected part of the mesh (vertex " +
                std::to_string(v) + ") has no fixed vertex");
        }
    }
    std::vector<Eigen::Triplet<double>> entries;
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        for (int a = 0; a <= D; ++a) {
            for (int b = a + 1; b <= D; ++b) {
                const Index fa = free_index_[mesh.simplices(s, a)],
                            fb = free_index_[mesh.simplices(s, b)];
                if (fa >= 0) entries.emplace_back(fa, fa, 1.0);
                if (fb >= 0) entries.emplace_back(fb, fb, 1.0);
                if (fa >= 0 && fb >= 0)
                    entries.emplace_back(std::max(fa, fb), std::min(fa, fb), -1.0);
            }
        }
    }
    Eigen::SparseMatrix<double> lower(num_free_, num_free_);
    lower.setFromTriplets(entries.begin(), entries.end());
    solver_ = std::make_unique<LinearSolver>(LinearSolverType::kAuto);
    solver_->analyze(lower);
    if (solver_->factorize(lower) != FactorizationStatus::kSuccess) {
        throw InvalidArgumentError("vertex recovery: the system could not be factored");
    }
}

template <int D>
Eigen::MatrixXd VertexRecovery<D>::recover(const std::vector<Mat<D>>& A,
                                           const Eigen::MatrixXd& positions) const {
    Eigen::MatrixXd result = positions.leftCols(D);
    if (num_free_ == 0) return result;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(num_free_, D);
    for (Index s = 0; s < mesh_.num_simplices(); ++s) {
        for (int a = 0; a <= D; ++a) {
            for (int b = a + 1; b <= D; ++b) {
                // |x_a - x_b - t|^2 with t = A (u_a - u_b).
                const Index va = mesh_.simplices(s, a), vb = mesh_.simplices(s, b);
                const Vec<D> t = A[s] * (frames_.corner(s, a) - frames_.corner(s, b));
                const Index fa = free_index_[va], fb = free_index_[vb];
                if (fa >= 0) {
                    rhs.row(fa) += t.transpose();
                    if (fb < 0) rhs.row(fa) += result.row(vb);
                }
                if (fb >= 0) {
                    rhs.row(fb) -= t.transpose();
                    if (fa < 0) rhs.row(fb) += result.row(va);
                }
            }
        }
    }
    const Eigen::MatrixXd x = solver_->solve_columns(rhs);
    for (Index v = 0; v < mesh_.num_vertices(); ++v) {
        if (free_index_[v] >= 0) result.row(v) = x.row(free_index_[v]);
    }
    return result;
}

template <int D>
Eigen::MatrixXd recover_vertices(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                                 const std::vector<Mat<D>>& A, const Eigen::MatrixXd& positions,
                                 const std::vector<unsigned char>& fixed) {
    return VertexRecovery<D>(mesh, frames, fixed).recover(A, positions);
}

template class VertexRecovery<2>;
template class VertexRecovery<3>;
template Eigen::MatrixXd recover_vertices<2>(const SimplicialMesh&, const RestFrames<2>&,
                                             const std::vector<Mat<2>>&, const Eigen::MatrixXd&,
                                             const std::vector<unsigned char>&);
template Eigen::MatrixXd recover_vertices<3>(const SimplicialMesh&, const RestFrames<3>&,
                                             const std::vector<Mat<3>>&, const Eigen::MatrixXd&,
                                             const std::vector<unsigned char>&);

}  // namespace sa
