#include <gtest/gtest.h>
#include <omp.h>

#include <atomic>

#include "optim/linear_solver.h"
#include "optim/serial_openmp.h"

namespace sa {
namespace {

// Threads that ran the body of one `#pragma omp parallel` region.
int threads_in_a_region() {
    std::atomic<int> threads{0};
#pragma omp parallel num_threads(2)
    { threads.fetch_add(1); }
    return threads.load();
}

TEST(SerialOpenMP, RunsRegionsOnTheCallingThreadOnlyInsideAScope) {
    const long before = serial_openmp_regions();
    {
        const SerialOpenMP serial;
        EXPECT_EQ(threads_in_a_region(), 1);
        {
            const SerialOpenMP nested;
            EXPECT_EQ(threads_in_a_region(), 1);
        }
        EXPECT_EQ(threads_in_a_region(), 1);
    }
    EXPECT_EQ(serial_openmp_regions(), before + 3);
    // Outside a scope the OpenMP runtime runs the region: a team of two, here as anywhere.
    EXPECT_EQ(threads_in_a_region(), 2);
    EXPECT_EQ(serial_openmp_regions(), before + 3);
}

// A 2D grid Laplacian: large enough for CHOLMOD's supernodal factorization to open its parallel
// regions, which run serially and still give the solution.
TEST(SerialOpenMP, CholmodSupernodalRunsItsRegionsSeriallyAndSolves) {
    const int side = 80, n = side * side;
    std::vector<Eigen::Triplet<double>> entries;
    for (int j = 0; j < side; ++j) {
        for (int i = 0; i < side; ++i) {
            const int v = j * side + i;
            entries.emplace_back(v, v, 4.01);
            if (i + 1 < side) entries.emplace_back(v + 1, v, -1.0);
            if (j + 1 < side) entries.emplace_back(v + side, v, -1.0);
        }
    }
    Eigen::SparseMatrix<double> lower(n, n);
    lower.setFromTriplets(entries.begin(), entries.end());
    LinearSolver solver(LinearSolverType::kCholmodSupernodal);
    solver.analyze(lower);
    const long before = serial_openmp_regions();
    ASSERT_EQ(solver.factorize(lower), FactorizationStatus::kSuccess);
    EXPECT_GT(serial_openmp_regions(), before);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0);
    const Eigen::VectorXd x = solver.solve(b);
    const Eigen::SparseMatrix<double> full = lower.selfadjointView<Eigen::Lower>();
    EXPECT_LT((full * x - b).norm() / b.norm(), 1e-10);
}

}  // namespace
}  // namespace sa
