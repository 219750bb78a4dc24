#include "geometry/vertex_recovery.h"

#include <Eigen/Sparse>
#include <numeric>

#include "optim/errors.h"
#include "optim/linear_solver.h"

namespace sa {

template <int D>
Eigen::MatrixXd recover_vertices(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                                 const std::vector<Mat<D>>& A, const Eigen::MatrixXd& positions,
                                 const std::vector<unsigned char>& fixed) {
    const Index nv = mesh.num_vertices();
    Eigen::MatrixXd result = positions.leftCols(D);
    std::vector<unsigned char> used(nv, 0);
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        for (int k = 0; k <= D; ++k) used[mesh.simplices(s, k)] = 1;
    }
    std::vector<Index> free_index(nv, -1);
    Index nf = 0;
    for (Index v = 0; v < nv; ++v) {
        if (used[v] && !fixed[v]) free_index[v] = nf++;
    }
    if (nf == 0) return result;

    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nf, D);
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        for (int a = 0; a <= D; ++a) {
            for (int b = a + 1; b <= D; ++b) {
                const Index va = mesh.simplices(s, a), vb = mesh.simplices(s, b);
                // |x_a - x_b - t|^2 with t = A (u_a - u_b).
                const Vec<D> t = A[s] * (frames.corner(s, a) - frames.corner(s, b));
                const Index fa = free_index[va], fb = free_index[vb];
                if (fa >= 0) {
                    entries.emplace_back(fa, fa, 1.0);
                    rhs.row(fa) += t.transpose();
                    if (fb < 0) rhs.row(fa) += result.row(vb);
                }
                if (fb >= 0) {
                    entries.emplace_back(fb, fb, 1.0);
                    rhs.row(fb) -= t.transpose();
                    if (fa < 0) rhs.row(fb) += result.row(va);
                }
                if (fa >= 0 && fb >= 0)
                    entries.emplace_back(std::max(fa, fb), std::min(fa, fb), -1.0);
            }
        }
    }
    Eigen::SparseMatrix<double> lower(nf, nf);
    lower.setFromTriplets(entries.begin(), entries.end());
    LinearSolver solver(LinearSolverType::kCholmodSupernodal);
    solver.analyze(lower);
    if (solver.factorize(lower) != FactorizationStatus::kSuccess) {
        throw InvalidArgumentError(
            "recover_vertices: the system is singular: a connected part of the mesh has no fixed "
            "vertex");
    }
    for (int c = 0; c < D; ++c) {
        const Eigen::VectorXd x = solver.solve(rhs.col(c));
        for (Index v = 0; v < nv; ++v) {
            if (free_index[v] >= 0) result(v, c) = x[free_index[v]];
        }
    }
    return result;
}

template Eigen::MatrixXd recover_vertices<2>(const SimplicialMesh&, const RestFrames<2>&,
                                             const std::vector<Mat<2>>&, const Eigen::MatrixXd&,
                                             const std::vector<unsigned char>&);
template Eigen::MatrixXd recover_vertices<3>(const SimplicialMesh&, const RestFrames<3>&,
                                             const std::vector<Mat<3>>&, const Eigen::MatrixXd&,
                                             const std::vector<unsigned char>&);

}  // namespace sa
