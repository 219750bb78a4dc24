// The two triangular substitutions of a supernodal Cholesky solve, CHOLMOD's (cholmod_solve, one
// thread) against SupernodalSolve's (optim/detail/supernodal_solve.h) on one and two threads, on
// the factor of a generated 3D system: an n x n x n grid of nodes with 3 unknowns each, every node
// coupled to its 26 neighbours (the pattern of a tetrahedral mesh's vertex Hessian, denser). Prints
// a table of the median of the repetitions, in milliseconds, and the bitwise comparison of the one-
// and two-thread results. --matrix takes a symmetric matrix instead (its lower triangle, or the
// whole, in Matrix Market format, as Eigen's saveMarket writes it).
//
//   bench_triangular_solve [--grid 20 | --matrix H.mtx] [--repetitions 50] [--refactor]
#include <cholmod.h>
#include <tbb/task_arena.h>

#include <CLI/CLI.hpp>
#include <Eigen/CholmodSupport>
#include <algorithm>
#include <chrono>
#include <cstring>
#include <functional>
#include <iomanip>
#include <iostream>
#include <unsupported/Eigen/SparseExtra>

#include "optim/detail/supernodal_solve.h"

namespace {

Eigen::SparseMatrix<double> grid_system_lower(int n) {
    const int unknowns = 3 * n * n * n;
    auto node = [n](int i, int j, int k) { return (k * n + j) * n + i; };
    std::vector<Eigen::Triplet<double>> entries;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                for (int dk = -1; dk <= 1; ++dk)
                    for (int dj = -1; dj <= 1; ++dj)
                        for (int di = -1; di <= 1; ++di) {
                            const int a = i + di, b = j + dj, c = k + dk;
                            if (a < 0 || b < 0 || c < 0 || a >= n || b >= n || c >= n) continue;
                            const int p = node(i, j, k), q = node(a, b, c);
                            if (q < p) continue;
                            for (int x = 0; x < 3; ++x)
                                for (int y = 0; y < 3; ++y) {
                                    const int row = 3 * q + x, col = 3 * p + y;
                                    if (row < col) continue;
                                    const double v = p == q ? (x == y ? 60.0 : 1.0) : -0.5;
                                    entries.emplace_back(row, col, v);
                                }
                        }
    Eigen::SparseMatrix<double> m(unknowns, unknowns);
    m.setFromTriplets(entries.begin(), entries.end());
    return m;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

/// Median milliseconds of each variant, the variants taking turns within every repetition so
/// that the machine's drift affects them alike; `before` runs untimed before each of them.
std::vector<double> alternating_median_ms(int repetitions,
                                          const std::vector<std::function<void()>>& variants,
                                          const std::function<void()>& before) {
    std::vector<std::vector<double>> times(variants.size());
    for (int r = 0; r < repetitions; ++r) {
        for (std::size_t v = 0; v < variants.size(); ++v) {
            before();
            const auto start = std::chrono::steady_clock::now();
            variants[v]();
            times[v].push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
        }
    }
    std::vector<double> medians;
    for (auto& t : times) medians.push_back(median(t));
    return medians;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Supernodal triangular solves: CHOLMOD against SupernodalSolve"};
    int grid = 20, repetitions = 50;
    std::string matrix_file;
    bool refactor = false;
    app.add_option("--grid", grid, "nodes per side of the grid (3 unknowns each)")
        ->check(CLI::Range(4, 200));
    app.add_option("--repetitions", repetitions, "solves timed per variant")
        ->check(CLI::PositiveNumber);
    app.add_option("--matrix", matrix_file, "Matrix Market file of a symmetric matrix")
        ->check(CLI::ExistingFile);
    app.add_flag("--refactor", refactor,
                 "factor again (untimed) before every solve, as a Newton iteration does");
    CLI11_PARSE(app, argc, argv);

    Eigen::SparseMatrix<double> lower;
    if (matrix_file.empty()) {
        lower = grid_system_lower(grid);
    } else if (!Eigen::loadMarket(lower, matrix_file) || lower.rows() != lower.cols()) {
        std::cerr << matrix_file << ": not a square Matrix Market matrix\n";
        return 1;
    }
    cholmod_common common;
    cholmod_start(&common);
    common.print = 0;
    common.supernodal = CHOLMOD_SUPERNODAL;
    common.nrelax[0] = 16;  // as the linear solver relaxes them
    common.nrelax[1] = 64;
    common.nrelax[2] = 128;
    cholmod_sparse a = Eigen::viewAsCholmod(lower);
    a.stype = -1;
    cholmod_factor* factor = cholmod_analyze(&a, &common);
    cholmod_factorize(&a, factor, &common);
    if (common.status != CHOLMOD_OK || !factor->is_super) {
        std::cerr << "factorization failed (CHOLMOD status " << common.status << ")\n";
        return 1;
    }
    const int n = static_cast<int>(factor->n);
    const sa::SupernodalSolve plan(
        {n, static_cast<int>(factor->nsuper), static_cast<const int*>(factor->super),
         static_cast<const int*>(factor->pi), static_cast<const int*>(factor->px),
         static_cast<const int*>(factor->s)});
    const long values = static_cast<const int*>(factor->px)[factor->nsuper];

    Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0).array().sin();
    cholmod_dense rhs = Eigen::viewAsCholmod(b);
    // CHOLMOD solves P^T L^-T L^-1 P b; SupernodalSolve works in the factor's ordering, as the
    // linear solver uses it (the permutation is applied outside, in O(n)).
    Eigen::VectorXd one, two;
    tbb::task_arena one_thread(1), two_threads(2);
    auto ours = [&](tbb::task_arena& arena, Eigen::VectorXd& out) {
        return [&] {
            out = b;
            arena.execute(
                [&] { plan.solve_in_place(static_cast<const double*>(factor->x), out.data()); });
        };
    };
    const std::vector<double> ms = alternating_median_ms(
        repetitions,
        {[&] {
             cholmod_dense* x = cholmod_solve(CHOLMOD_A, factor, &rhs, &common);
             cholmod_free_dense(&x, &common);
         },
         ours(one_thread, one), ours(two_threads, two)},
        [&] {
            // As in a Newton iteration: the solve follows the factorization, which leaves in the
            // caches what it wrote last.
            if (refactor) cholmod_factorize(&a, factor, &common);
        });
    const double cholmod_ms = ms[0], one_ms = ms[1], two_ms = ms[2];

    std::cout << (matrix_file.empty() ? "grid " + std::to_string(grid) + "^3 x 3" : matrix_file)
              << ": " << n << " unknowns, " << factor->nsuper << " supernodes, " << values
              << " factor values (" << std::fixed << std::setprecision(1) << values * 8e-6
              << " MB); serial share of the split " << std::setprecision(3) << plan.serial_share()
              << "\n\n"
              << "| solve | median ms |\n|---|---:|\n"
              << "| cholmod_solve, 1 thread | " << cholmod_ms << " |\n"
              << "| SupernodalSolve, 1 thread | " << one_ms << " |\n"
              << "| SupernodalSolve, 2 threads | " << two_ms << " |\n\n"
              << "one- and two-thread results bitwise equal: "
              << (std::memcmp(one.data(), two.data(), sizeof(double) * n) == 0 ? "yes" : "NO")
              << "\n";
    cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
    return 0;
}
