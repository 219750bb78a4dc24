// Bends a 2D bar by a quarter turn without inverting a triangle, written as a user of sa::optim
// would: a symmetric Dirichlet energy over vertex positions (derivatives by automatic
// differentiation, its own max_step), a quadratic pull on the right end, a fixed left end.
#include <iostream>

#include "optim/optim.h"

using sa::Index;

// The edge matrix [p1 - p0, p2 - p0] of a triangle given as (x0, y0, x1, y1, x2, y2).
template <class T>
Eigen::Matrix<T, 2, 2> edges(const Eigen::Matrix<T, 6, 1>& x) {
    return (Eigen::Matrix<T, 2, 2>() << x[2] - x[0], x[4] - x[0], x[3] - x[1], x[5] - x[1])
        .finished();
}

// area * (|J|^2 + |J^-1|^2), J the triangle's Jacobian; +inf when inverted.
struct SymmetricDirichlet : sa::AutodiffEnergy<SymmetricDirichlet, 6> {
    std::vector<Eigen::Matrix2d> rest_inverse;
    std::vector<double> area;

    template <class T>
    T energy(Index t, const Eigen::Matrix<T, 6, 1>& x) const {
        const Eigen::Matrix<T, 2, 2> J = edges(x) * rest_inverse[t];
        const T det = J.determinant();
        if (det <= 0.0) return T(sa::kInfinity);
        return area[t] * J.squaredNorm() * (1.0 + 1.0 / (det * det));
    }
    // The first s > 0 with det(E + s D) = a s^2 + b s + c = 0: the triangle flips there.
    double max_step(Index, const sa::Vec<6>& x, const sa::Vec<6>& dx) const {
        const Eigen::Matrix2d E = edges<double>(x), D = edges<double>(dx);
        const double a = D.determinant(), c = E.determinant(), b = (E + D).determinant() - a - c;
        const double disc = b * b - 4.0 * a * c;
        if (a == 0.0 || disc < 0.0) return a == 0.0 && b < 0.0 ? -c / b : sa::kInfinity;
        const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b)), r1 = q / a, r2 = c / q;
        return std::min(r1 > 0.0 ? r1 : sa::kInfinity, r2 > 0.0 ? r2 : sa::kInfinity);
    }
};

// |p - target|^2 for one vertex (x, y): quadratic, so its Hessian is assembled once.
struct Pull : sa::AutodiffEnergy<Pull, 2> {
    static constexpr bool is_quadratic = true;
    std::vector<Eigen::Vector2d> target;
    template <class T>
    T energy(Index i, const Eigen::Matrix<T, 2, 1>& p) const {
        return (p - target[i]).squaredNorm();
    }
};

int main() {
    const int nx = 41, ny = 5;  // a bar of length 8 and width 1, bent around (0, radius)
    const double length = 8.0, radius = length / (M_PI / 2.0);
    Eigen::VectorXd x(2 * nx * ny);
    for (int v = 0; v < nx * ny; ++v)
        x.segment<2>(2 * v) << length * (v % nx) / (nx - 1), (v / nx) / (ny - 1.0);

    SymmetricDirichlet distortion;
    std::vector<std::array<Index, 6>> triangles;
    auto add_triangle = [&](int a, int b, int c) {
        triangles.push_back({2 * a, 2 * a + 1, 2 * b, 2 * b + 1, 2 * c, 2 * c + 1});
        const Eigen::Matrix2d rest = edges<double>(x(triangles.back()));
        distortion.rest_inverse.push_back(rest.inverse());
        distortion.area.push_back(0.5 * rest.determinant());
    };
    for (int v = 0; v < nx * (ny - 1); ++v)
        if (v % nx != nx - 1)
            add_triangle(v, v + 1, v + nx + 1), add_triangle(v, v + nx + 1, v + nx);

    sa::Problem problem(x);
    Pull pull;
    std::vector<std::array<Index, 2>> pulled;
    for (int j = 0; j < ny; ++j) {  // the left end stays, the right end is pulled round the bend
        problem.set_fixed(2 * j * nx);
        problem.set_fixed(2 * j * nx + 1);
        pulled.push_back({2 * (j * nx + nx - 1), 2 * (j * nx + nx - 1) + 1});
        pull.target.emplace_back(radius - j / (ny - 1.0), radius);
    }
    problem.add_term("symmetric Dirichlet", distortion, triangles);
    problem.add_term("pull", pull, pulled, 1e3);

    sa::NewtonOptions options;
    options.callbacks.push_back(sa::ProgressPrinter(std::cout));
    const sa::NewtonSummary summary = sa::solve(problem, options);
    std::cout << summary.full_report();

    int inverted = 0;  // verified from the vertex positions
    for (const auto& t : triangles)
        inverted += edges<double>(problem.variables()(t)).determinant() <= 0.0;
    std::cout << "verified from vertex positions: " << inverted << " of " << triangles.size()
              << " triangles inverted\n";
    return summary.success() && inverted == 0 ? 0 : 1;
}
