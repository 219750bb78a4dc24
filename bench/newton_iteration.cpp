// One Newton iteration on a problem shaped like 2D Simplex Assembly: a 2x2 matrix A_i per
// triangle of a generated grid mesh (4 variables, the conformal barrier e^{d}), and an edge
// assembly term per interior edge (8 variables, quadratic). Prints the time of each phase for
// each thread count, and the two ratios the optimizer is held to:
//   overhead / factorize   everything but the numeric factorization, relative to it (<= 25%)
//   (evaluate + project) speed-up from 1 to 2 threads (>= 1.7x)
//
//   bench_newton_iteration [--triangles N] [--threads 1,2]
#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <Eigen/Geometry>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>

#include "energies/edge_assembly_energy.h"
#include "energies/simplex_energy.h"
#include "optim/optim.h"

namespace {

using sa::Index;

struct Shape {
    int nx, ny;  // grid cells
    std::vector<std::array<Index, 4>> simplices;
    std::vector<std::array<Index, 8>> couplings;
    std::vector<sa::SharedFacetEdges<2>> facets;
    Eigen::VectorXd variables;
};

// nx * ny cells of two triangles each; random A_i with singular values in [0.7, 1.4].
Shape make_shape(long triangles) {
    Shape s;
    s.nx = s.ny = std::max(1, int(std::lround(std::sqrt(triangles / 2.0))));
    const int n = 2 * s.nx * s.ny;
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI), scale(0.7, 1.4);
    s.variables.resize(4 * n);
    for (int t = 0; t < n; ++t) {
        const Eigen::Rotation2Dd r(angle(rng)), q(angle(rng));
        const sa::Mat<2> A = r.toRotationMatrix() *
                             Eigen::Vector2d(scale(rng), scale(rng)).asDiagonal() *
                             q.toRotationMatrix();
        s.variables.segment<4>(4 * t) = Eigen::Map<const sa::Vec<4>>(A.data());
        s.simplices.push_back({4 * t, 4 * t + 1, 4 * t + 2, 4 * t + 3});
    }
    // Cell (i, j) holds triangles 2c (lower right) and 2c + 1 (upper left), c = j * nx + i.
    auto couple = [&](int a, int b, const Eigen::Vector2d& edge) {
        std::array<Index, 8> e;
        for (int k = 0; k < 4; ++k) e[k] = 4 * a + k, e[4 + k] = 4 * b + k;
        s.couplings.push_back(e);
        sa::SharedFacetEdges<2> facet;
        facet.in_i = facet.in_j = edge.normalized();
        s.facets.push_back(facet);
    };
    for (int j = 0; j < s.ny; ++j) {
        for (int i = 0; i < s.nx; ++i) {
            const int c = j * s.nx + i;
            couple(2 * c, 2 * c + 1, {1.0, 1.0});                             // diagonal
            if (i + 1 < s.nx) couple(2 * c, 2 * (c + 1) + 1, {0.0, 1.0});     // right
            if (j + 1 < s.ny) couple(2 * c + 1, 2 * (c + s.nx), {1.0, 0.0});  // top
        }
    }
    return s;
}

double peak_memory_gb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.0 / 1024.0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"One Newton iteration on a Simplex-Assembly-shaped problem, per phase"};
    long triangles = 1000000;
    std::vector<int> thread_counts = {1, 2};
    app.add_option("--triangles", triangles, "number of triangles (rounded to a square grid)")
        ->check(CLI::PositiveNumber);
    app.add_option("--threads", thread_counts, "thread counts to run")->delimiter(',');
    CLI11_PARSE(app, argc, argv);

    const Shape shape = make_shape(triangles);
    std::cout << "problem: " << shape.simplices.size() << " triangles (4 variables each), "
              << shape.couplings.size() << " interior edges (8 variables each), "
              << shape.variables.size() << " variables\n\n";

    std::cout << "| threads | evaluate | project | assemble | factorize | solve | line search | "
                 "overhead / factorize | setup (once) | analyze (once) |\n"
                 "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    std::vector<double> evaluate_project;
    for (int threads : thread_counts) {
        sa::set_blas_threads(threads);
        sa::Problem problem(shape.variables);
        sa::SimplexEnergyOptions options;  // conformal barrier, K = inf, E_m = 0
        problem.add_term(
            "barrier",
            sa::SimplexEnergy<2>(options, std::vector<double>(shape.simplices.size(), 1.0)),
            shape.simplices);
        problem.add_term("edge assembly", sa::EdgeAssemblyEnergy<2>(shape.facets), shape.couplings,
                         1e4);

        sa::NewtonOptions newton;
        newton.num_threads = threads;
        newton.max_iterations = 1;
        newton.gradient_tolerance = newton.decrement_tolerance = 0.0;
        const sa::NewtonSummary summary = sa::solve(problem, newton);
        if (summary.num_steps() != 1) {
            std::cerr << "expected one Newton step: " << summary.message << "\n";
            return 1;
        }
        const sa::PhaseTimes& t = summary.times;
        const double overhead = t.evaluate + t.project + t.assemble + t.solve + t.line_search;
        evaluate_project.push_back(t.evaluate + t.project);
        std::cout << std::fixed << std::setprecision(3) << "| " << threads << " | " << t.evaluate
                  << " | " << t.project << " | " << t.assemble << " | " << t.factorize << " | "
                  << t.solve << " | " << t.line_search << " | " << std::setprecision(1)
                  << 100.0 * overhead / t.factorize << "% | " << std::setprecision(3) << t.setup
                  << " | " << t.analyze << " |\n";
    }
    std::cout << "\n";
    if (evaluate_project.size() >= 2) {
        std::cout << std::setprecision(2) << "evaluate + project speed-up, " << thread_counts[0]
                  << " -> " << thread_counts[1]
                  << " threads: " << evaluate_project[0] / evaluate_project[1] << "x\n";
    }
    std::cout << "peak memory: " << std::setprecision(2) << peak_memory_gb() << " GB\n"
              << "(times in seconds, one iteration each; line search includes the largest "
                 "feasible step)\n";
    return 0;
}
