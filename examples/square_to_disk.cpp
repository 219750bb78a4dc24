// Maps a square grid onto the unit disk without inverting a triangle: a lambda energy of the
// user's own (boundary vertices pulled onto the circle) composed with a built-in one of
// sa::energies (Simplex Assembly's per-simplex energy, a symmetric Dirichlet distortion plus the
// conformal barrier, on vertex positions, with its exact max_step and its own projection).
#include <iostream>

#include "energies/vertex_copy_energies.h"
#include "optim/optim.h"

using sa::Index;

int main() {
    const int n = 16;  // n x n cells of two triangles on [-1, 1]^2
    Eigen::MatrixXd V((n + 1) * (n + 1), 2);
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) V.row(j * (n + 1) + i) << 2.0 * i / n - 1, 2.0 * j / n - 1;
    Eigen::MatrixXi F(2 * n * n, 3);
    for (int j = 0, t = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int v = j * (n + 1) + i;
            F.row(t++) << v, v + 1, v + n + 2;
            F.row(t++) << v, v + n + 2, v + n + 1;
        }

    // The built-in energy: per triangle, mu * area * d_m(A) + E_C(A), A = edges * rest^-1.
    std::vector<double> area;
    std::vector<Eigen::Matrix2d> rest_inverse;
    for (Index t = 0; t < F.rows(); ++t) {
        Eigen::Matrix2d rest;
        rest << V.row(F(t, 1)) - V.row(F(t, 0)), V.row(F(t, 2)) - V.row(F(t, 0));
        rest.transposeInPlace();
        rest_inverse.push_back(rest.inverse());
        area.push_back(0.5 * rest.determinant());
    }
    sa::SimplexEnergyOptions options;
    options.mapping_distortion = sa::DistortionType::kSymmetricDirichlet;
    options.mu = 1.0;
    sa::VertexSimplexEnergy<2> distortion(sa::SimplexEnergy<2>(options, area), rest_inverse);

    sa::Problem problem(sa::flatten_points(V));
    problem.add_term("distortion", distortion, sa::simplex_variables<2, 3>(F));

    // The user's energy, a lambda: (|p| - 1)^2 for each boundary vertex.
    std::vector<std::array<Index, 2>> boundary;
    for (Index v = 0; v < V.rows(); ++v)
        if (V.row(v).cwiseAbs().maxCoeff() == 1.0) boundary.push_back(sa::point_variables<2>(v));
    problem.add_elements<2>(
        "on the circle", boundary,
        [](auto const& p, Index) {
            using std::sqrt;
            const auto off = sqrt(p.squaredNorm()) - 1.0;
            return off * off;
        },
        1e6);

    sa::NewtonOptions newton;
    newton.callbacks.push_back(sa::ProgressPrinter(std::cout));
    const sa::NewtonSummary summary = sa::solve(problem, newton);
    std::cout << summary.full_report();

    const Eigen::MatrixXd U = sa::unflatten_points<2>(problem.variables());
    int inverted = 0;  // verified from the vertex positions
    for (Index t = 0; t < F.rows(); ++t) {
        Eigen::Matrix2d e;
        e << U.row(F(t, 1)) - U.row(F(t, 0)), U.row(F(t, 2)) - U.row(F(t, 0));
        inverted += e.determinant() <= 0.0;
    }
    double off_circle = 0.0;
    for (const auto& b : boundary)
        off_circle = std::max(off_circle, std::abs(U.row(b[0] / 2).norm() - 1.0));
    std::cout << "verified from vertex positions: " << inverted << " of " << F.rows()
              << " triangles inverted, boundary within " << off_circle << " of the circle\n";
    return summary.success() && inverted == 0 && off_circle < 1e-2 ? 0 : 1;
}
