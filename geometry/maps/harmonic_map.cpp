#include "geometry/maps/harmonic_map.h"

#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include "optim/errors.h"
#include "optim/linear_solver.h"

namespace sa {

Eigen::MatrixXd harmonic_map(const SimplicialMesh& mesh, const std::vector<Index>& fixed_vertices,
                             const Eigen::MatrixXd& fixed_positions, LaplacianWeights weights) {
    if (mesh.simplex_dimension() != 2)
        throw InvalidArgumentError("harmonic_map: needs a triangle mesh");
    if (fixed_positions.rows() != Index(fixed_vertices.size())) {
        throw InvalidArgumentError("harmonic_map: " + std::to_string(fixed_positions.rows()) +
                                   " positions for " + std::to_string(fixed_vertices.size()) +
                                   " fixed vertices");
    }
    const Index nv = mesh.num_vertices();
    const Index c = fixed_positions.cols();
    Eigen::MatrixXd x = Eigen::MatrixXd::Zero(nv, c);
    std::vector<Index> free_index(nv, 0);
    for (std::size_t k = 0; k < fixed_vertices.size(); ++k) {
        free_index[fixed_vertices[k]] = -1;
        x.row(fixed_vertices[k]) = fixed_positions.row(k);
    }
    Index nf = 0;
    for (Index v = 0; v < nv; ++v) {
        if (free_index[v] >= 0) free_index[v] = nf++;
    }
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nf, c);
    auto add = [&](Index a, Index b, double w) {  // w (x_a - x_b)^2
        const Index fa = free_index[a], fb = free_index[b];
        if (fa >= 0) {
            entries.emplace_back(fa, fa, w);
            if (fb < 0) rhs.row(fa) += w * x.row(b);
        }
        if (fb >= 0) {
            entries.emplace_back(fb, fb, w);
            if (fa < 0) rhs.row(fb) += w * x.row(a);
        }
        if (fa >= 0 && fb >= 0) entries.emplace_back(std::max(fa, fb), std::min(fa, fb), -w);
    };
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        for (int k = 0; k < 3; ++k) {
            const Index a = mesh.simplices(s, (k + 1) % 3), b = mesh.simplices(s, (k + 2) % 3);
            double w = 0.5;  // each interior edge is seen from two triangles
            if (weights == LaplacianWeights::kCotangent) {
                // Half the cotangent of the angle opposite edge (a, b), at vertex k; clamped to
                // stay positive so that the system is definite.
                Eigen::Vector3d p[3];
                for (int m = 0; m < 3; ++m) {
                    p[m].setZero();
                    p[m].head(mesh.ambient_dimension()) =
                        mesh.vertices.row(mesh.simplices(s, (k + m) % 3)).transpose();
                }
                const Eigen::Vector3d u = p[1] - p[0], v = p[2] - p[0];
                w = std::max(0.5 * u.dot(v) / u.cross(v).norm(), 1e-8);
            }
            add(a, b, w);
        }
    }
    if (nf == 0) return x;
    Eigen::SparseMatrix<double> lower(nf, nf);
    lower.setFromTriplets(entries.begin(), entries.end());
    LinearSolver solver(LinearSolverType::kCholmodSupernodal,
                        FillOrdering::kAmd);  // one factorization
    solver.analyze(lower);
    if (solver.factorize(lower) != FactorizationStatus::kSuccess) {
        throw InvalidArgumentError(
            "harmonic_map: singular system: a connected part has no fixed vertex");
    }
    for (Index j = 0; j < c; ++j) {
        const Eigen::VectorXd sol = solver.solve(rhs.col(j));
        for (Index v = 0; v < nv; ++v) {
            if (free_index[v] >= 0) x(v, j) = sol[free_index[v]];
        }
    }
    return x;
}

}  // namespace sa
