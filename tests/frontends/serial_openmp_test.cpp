// The sa command's GOMP_parallel (frontends/cli/serial_openmp.h), linked into this test as into
// the command: OpenMP regions run on the calling thread, CHOLMOD's included.
#include <gtest/gtest.h>
#include <omp.h>

#include <atomic>
#include <thread>

#include "frontends/cli/serial_openmp.h"
#include "optim/linear_solver.h"

namespace sa::cli {
namespace {

// Threads that ran the body of one `#pragma omp parallel` region, and whether the caller was one.
int threads_in_a_region(bool* on_caller) {
    std::atomic<int> threads{0};
    const std::thread::id caller = std::this_thread::get_id();
    std::atomic<bool> caller_ran{false};
#pragma omp parallel num_threads(2)
    {
        threads.fetch_add(1);
        if (std::this_thread::get_id() == caller) caller_ran = true;
        EXPECT_EQ(omp_get_thread_num(), 0);
        EXPECT_EQ(omp_get_num_threads(), 1);
    }
    *on_caller = caller_ran;
    return threads.load();
}

TEST(SerialOpenMP, RegionsRunOnceOnTheCallingThreadOfAnyThread) {
    const long before = serial_openmp_regions();
    bool on_caller = false;
    EXPECT_EQ(threads_in_a_region(&on_caller), 1);
    EXPECT_TRUE(on_caller);
    std::thread other([&] {
        bool other_on_caller = false;
        EXPECT_EQ(threads_in_a_region(&other_on_caller), 1);
        EXPECT_TRUE(other_on_caller);
    });
    other.join();
    EXPECT_EQ(serial_openmp_regions(), before + 2);
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
}  // namespace sa::cli
