#include "frontends/hex/grid_start.h"

#include <Eigen/LU>
#include <Eigen/Sparse>
#include <cmath>
#include <string>

#include "optim/errors.h"
#include "optim/linear_solver.h"

namespace sa {

Eigen::MatrixXd grid_start(const Eigen::MatrixXi& tets, const Eigen::MatrixXd& map,
                           const std::vector<std::array<int, 3>>& plane_of_vertex,
                           const std::vector<double>& coordinates,
                           const PlaneQuantization& quantization) {
    const Index nv = static_cast<Index>(map.rows()), nt = static_cast<Index>(tets.rows());
    if (map.cols() != 3 || tets.cols() != 4 || static_cast<Index>(plane_of_vertex.size()) != nv ||
        quantization.position.size() != coordinates.size() || !(quantization.cell > 0.0)) {
        throw InvalidArgumentError("grid_start: mismatched sizes");
    }
    const double h = quantization.cell;
    const Eigen::MatrixXd x = map / h;
    // Per tetrahedron: vol G^T G, G the gradients of its barycentric functions (3 x 4).
    std::vector<Eigen::Matrix4d> stiffness(nt);
    for (Index t = 0; t < nt; ++t) {
        Eigen::Matrix3d edges;
        const Eigen::Vector3d p0 = x.row(tets(t, 0)).transpose();
        for (int k = 0; k < 3; ++k) edges.col(k) = x.row(tets(t, k + 1)).transpose() - p0;
        const double det = edges.determinant();
        if (!(std::abs(det) > 0.0) || !std::isfinite(det)) {
            throw InvalidArgumentError("grid_start: tetrahedron " + std::to_string(t) +
                                       " is flat in the PolyCube map");
        }
        Eigen::Matrix<double, 3, 4> g;
        g.rightCols<3>() = edges.inverse().transpose();
        g.col(0) = -g.rightCols<3>().rowwise().sum();
        stiffness[t] = (std::abs(det) / 6.0) * g.transpose() * g;
    }
    Eigen::MatrixXd start = x;
    for (int axis = 0; axis < 3; ++axis) {
        // Fixed displacements on the planes of this axis; the other vertices are unknowns.
        Eigen::VectorXd d = Eigen::VectorXd::Zero(nv);
        std::vector<Index> unknown(nv, -1);
        Index n = 0;
        for (Index v = 0; v < nv; ++v) {
            const int p = plane_of_vertex[v][axis];
            if (p >= 0)
                d[v] = quantization.position[p] - coordinates[p] / h;
            else
                unknown[v] = n++;
        }
        if (n == nv) continue;  // no plane of this axis: nothing moves along it
        std::vector<Eigen::Triplet<double>> entries;
        entries.reserve(16 * std::size_t(nt));
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
        for (Index t = 0; t < nt; ++t) {
            const Eigen::Matrix4d& K = stiffness[t];
            for (int i = 0; i < 4; ++i) {
                const Index ui = unknown[tets(t, i)];
                if (ui < 0) continue;
                for (int j = 0; j < 4; ++j) {
                    const Index uj = unknown[tets(t, j)];
                    if (uj < 0)
                        rhs[ui] -= K(i, j) * d[tets(t, j)];
                    else if (uj <= ui)
                        entries.emplace_back(ui, uj, K(i, j));
                }
            }
        }
        if (n > 0) {
            Eigen::SparseMatrix<double> lower(n, n);
            lower.setFromTriplets(entries.begin(), entries.end());
            LinearSolver solver(LinearSolverType::kCholmodSupernodal, FillOrdering::kAmd);
            solver.analyze(lower);
            if (solver.factorize(lower) != FactorizationStatus::kSuccess) {
                throw InvalidArgumentError(
                    "grid_start: the displacement's system is singular (a part of the mesh "
                    "without a plane of axis " +
                    std::to_string(axis) + "?)");
            }
            const Eigen::VectorXd solution = solver.solve(rhs);
            for (Index v = 0; v < nv; ++v)
                if (unknown[v] >= 0) d[v] = solution[unknown[v]];
        }
        start.col(axis) += d;
    }
    return start;
}

}  // namespace sa
