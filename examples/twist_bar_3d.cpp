// Twists a tetrahedral bar by a quarter turn without inverting a tetrahedron, as a user of
// sa::optim would: a volumetric energy of one's own (3D symmetric Dirichlet over vertex positions,
// autodiff derivatives, max_step from the cubic det(E + s D) = 0), a lambda pull, a fixed end.
#include <Eigen/Geometry>
#include <iostream>

#include "energies/polynomial_roots.h"
#include "optim/optim.h"

using sa::Index;

// The edge matrix [p1 - p0, p2 - p0, p3 - p0] of a tetrahedron (x0 y0 z0 ... x3 y3 z3).
template <class T>
Eigen::Matrix<T, 3, 3> edges(const Eigen::Matrix<T, 12, 1>& x) {
    Eigen::Matrix<T, 3, 3> E;
    for (int j = 0; j < 3; ++j) E.col(j) = sa::point<3>(x, j + 1) - sa::point<3>(x, 0);
    return E;
}

// volume * (|J|^2 + |J^-1|^2), J the tetrahedron's Jacobian; +inf when inverted.
struct SymmetricDirichlet3D : sa::AutodiffEnergy<SymmetricDirichlet3D, 12> {
    std::vector<Eigen::Matrix3d> rest_inverse;
    std::vector<double> volume;
    Index num_elements() const { return Index(volume.size()); }  // checked by add_term

    template <class T>
    T energy(Index t, const Eigen::Matrix<T, 12, 1>& x) const {
        const Eigen::Matrix<T, 3, 3> J = edges(x) * rest_inverse[t];
        if (J.determinant() <= 0.0) return T(sa::kInfinity);
        return volume[t] * (J.squaredNorm() + J.inverse().squaredNorm());
    }
    // The first s > 0 with det(E + s D) = 0, a cubic: c0 + c1 s + c2 s^2 + c3 s^3.
    double max_step(Index, const sa::Vec<12>& x, const sa::Vec<12>& dx) const {
        const Eigen::Matrix3d E = edges<double>(x), D = edges<double>(dx);
        auto cofactor = [](const Eigen::Matrix3d& M) {
            Eigen::Matrix3d C;
            for (int j = 0; j < 3; ++j) C.col(j) = M.col((j + 1) % 3).cross(M.col((j + 2) % 3));
            return C;
        };
        return sa::smallest_positive_root(E.determinant(), cofactor(E).cwiseProduct(D).sum(),
                                          E.cwiseProduct(cofactor(D)).sum(), D.determinant());
    }
};

// The edge matrix of tetrahedron t (four vertex indices) of the mesh P.
Eigen::Matrix3d edges_of(const Eigen::MatrixXd& P, const Eigen::RowVector4i& t) {
    return edges<double>(sa::Vec<12>(sa::flatten_points(P(t, Eigen::all))));
}

int main() {
    const int nx = 12, n = 2;  // 12 x 2 x 2 cubes of side 1/2, six tetrahedra each
    auto vertex = [&](int i, int j, int k) { return (k * (n + 1) + j) * (nx + 1) + i; };
    Eigen::MatrixXd V((nx + 1) * (n + 1) * (n + 1), 3);
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= nx; ++i)
                V.row(vertex(i, j, k)) << 0.5 * i, 0.5 * j - 0.5, 0.5 * k - 0.5;
    Eigen::MatrixXi T(6 * nx * n * n, 4);  // Kuhn's six paths from corner 000 to 111
    const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    SymmetricDirichlet3D energy;
    for (int k = 0, row = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < nx; ++i)
                for (const auto& path : paths) {
                    int c[3] = {i, j, k};
                    Eigen::RowVector4i t(vertex(i, j, k), 0, 0, 0);
                    for (int s = 0; s < 3; ++s) ++c[path[s]], t[s + 1] = vertex(c[0], c[1], c[2]);
                    if (edges_of(V, t).determinant() < 0.0) std::swap(t[1], t[2]);
                    T.row(row++) = t;
                    energy.rest_inverse.push_back(edges_of(V, t).inverse());
                    energy.volume.push_back(edges_of(V, t).determinant() / 6.0);
                }

    sa::Problem problem(sa::flatten_points(V));
    problem.add_term("symmetric Dirichlet", energy, sa::simplex_variables<3, 4>(T));
    std::vector<std::array<Index, 3>> pulled;
    std::vector<Eigen::Vector3d> target;  // the right end turned by 90 degrees about the x axis
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j) {
            problem.set_fixed(sa::point_variables<3>(vertex(0, j, k)));
            const Eigen::Vector3d p = V.row(vertex(nx, j, k));
            pulled.push_back(sa::point_variables<3>(vertex(nx, j, k)));
            target.emplace_back(p.x(), -p.z(), p.y());
        }
    problem.add_elements<3>("pull", pulled, sa::per_element(target), [&](auto const& p, Index e) {
        return 1e3 * (p - target[e]).squaredNorm();
    });

    const sa::NewtonSummary summary = sa::solve(problem);
    std::cout << summary.full_report();
    const Eigen::MatrixXd result = sa::unflatten_points<3>(problem.variables());
    int inverted = 0;  // verified from the vertex positions
    for (Index t = 0; t < T.rows(); ++t) inverted += edges_of(result, T.row(t)).determinant() <= 0;
    double end_error = 0.0;
    for (std::size_t h = 0; h < pulled.size(); ++h)
        end_error =
            std::max(end_error, (result.row(pulled[h][0] / 3).transpose() - target[h]).norm());
    std::cout << "verified from vertex positions: " << inverted << " of " << T.rows()
              << " tetrahedra inverted, right end within " << end_error << " of its target\n";
    return summary.success() && inverted == 0 && end_error < 0.05 ? 0 : 1;
}
