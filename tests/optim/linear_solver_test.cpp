#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include <cstring>
#include <random>

#include "optim/linear_solver.h"

namespace sa {
namespace {

// Lower triangle of a 1D Laplacian plus `diagonal` * I: SPD for diagonal > 0, indefinite for
// sufficiently negative diagonal.
Eigen::SparseMatrix<double> laplacian_lower(int n, double diagonal) {
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i < n; ++i) {
        entries.emplace_back(i, i, 2.0 + diagonal);
        if (i + 1 < n) entries.emplace_back(i + 1, i, -1.0);
    }
    Eigen::SparseMatrix<double> m(n, n);
    m.setFromTriplets(entries.begin(), entries.end());
    return m;
}

class LinearSolverTest : public ::testing::TestWithParam<LinearSolverType> {};

TEST_P(LinearSolverTest, SolvesAPositiveDefiniteSystem) {
    const int n = 500;
    const Eigen::SparseMatrix<double> lower = laplacian_lower(n, 0.01);
    const Eigen::SparseMatrix<double> full =
        lower.selfadjointView<Eigen::Lower>() *
        Eigen::SparseMatrix<double>(Eigen::VectorXd::Ones(n).asDiagonal());
    LinearSolver solver(GetParam());
    solver.analyze(lower);
    ASSERT_EQ(solver.factorize(lower), FactorizationStatus::kSuccess);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0);
    const Eigen::VectorXd x = solver.solve(b);
    EXPECT_LT((full * x - b).norm() / b.norm(), 1e-10);
    if (GetParam() != LinearSolverType::kAuto) {
        EXPECT_EQ(solver.active_type(), GetParam());
    }
    Eigen::MatrixXd B(n, 3);
    B << b, b.cwiseAbs(), Eigen::VectorXd::Ones(n);
    const Eigen::MatrixXd X = solver.solve_columns(B);
    ASSERT_EQ(X.cols(), 3);
    EXPECT_LT((full * X - B).norm() / B.norm(), 1e-10);
    EXPECT_LT((X.col(0) - x).norm(), 1e-12 * x.norm());
}

TEST_P(LinearSolverTest, ReportsAnIndefiniteMatrix) {
    const Eigen::SparseMatrix<double> lower = laplacian_lower(50, -3.0);
    LinearSolver solver(GetParam());
    solver.analyze(lower);
    EXPECT_EQ(solver.factorize(lower), FactorizationStatus::kNotPositiveDefinite);
    // The same pattern factors once the matrix is made definite.
    EXPECT_EQ(solver.factorize(laplacian_lower(50, 0.5)), FactorizationStatus::kSuccess);
}

// A second analysis (another pattern) after factorizations: the supernodal solver factors a
// permuted copy of the first matrix and must start over.
TEST_P(LinearSolverTest, AnalyzesAgainForAnotherPattern) {
    LinearSolver solver(GetParam());
    solver.analyze(laplacian_lower(300, 0.01));
    ASSERT_EQ(solver.factorize(laplacian_lower(300, 0.01)), FactorizationStatus::kSuccess);
    const Eigen::SparseMatrix<double> lower = laplacian_lower(420, 0.02);
    solver.analyze(lower);
    ASSERT_EQ(solver.factorize(lower), FactorizationStatus::kSuccess);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(420, 2.0, -1.0);
    const Eigen::VectorXd x = solver.solve(b);
    EXPECT_LT((lower.selfadjointView<Eigen::Lower>() * x - b).norm() / b.norm(), 1e-10);
}

// Entries above the diagonal are ignored, as for a lower triangle.
TEST_P(LinearSolverTest, IgnoresTheUpperTriangle) {
    const Eigen::SparseMatrix<double> lower = laplacian_lower(200, 0.05);
    const Eigen::SparseMatrix<double> full = lower.selfadjointView<Eigen::Lower>();
    LinearSolver solver(GetParam());
    solver.analyze(full);
    ASSERT_EQ(solver.factorize(full), FactorizationStatus::kSuccess);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(200, -1.0, 3.0);
    const Eigen::VectorXd x = solver.solve(b);
    EXPECT_LT((full * x - b).norm() / b.norm(), 1e-10);
}

// A system large enough for the supernodal solver to split its substitutions over two threads
// (optim/detail/supernodal_solve.h): the same solution as CHOLMOD's own substitutions
// (solve_columns), and the same bits on one thread as on two.
TEST(LinearSolver, SplitSubstitutionsMatchCholmodsOnAnyThreadCount) {
    const int nx = 120, ny = 90, n = nx * ny;
    std::vector<Eigen::Triplet<double>> entries;
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const int v = j * nx + i;
            entries.emplace_back(v, v, 4.5);
            if (i + 1 < nx) entries.emplace_back(v + 1, v, -1.0);
            if (j + 1 < ny) entries.emplace_back(v + nx, v, -1.0);
        }
    }
    Eigen::SparseMatrix<double> lower(n, n);
    lower.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SparseMatrix<double> full = lower.selfadjointView<Eigen::Lower>();
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -3.0, 2.0).array().sin();
    Eigen::VectorXd x[2];
    for (int threads : {1, 2}) {
        tbb::task_arena(threads).execute([&] {
            LinearSolver solver(LinearSolverType::kCholmodSupernodal);
            solver.analyze(lower);
            ASSERT_EQ(solver.factorize(lower), FactorizationStatus::kSuccess);
            x[threads - 1] = solver.solve(b);
            EXPECT_LT((x[threads - 1] - solver.solve_columns(b)).norm(), 1e-12 * x[0].norm());
        });
    }
    EXPECT_LT((full * x[0] - b).norm() / b.norm(), 1e-12);
    EXPECT_EQ(std::memcmp(x[0].data(), x[1].data(), sizeof(double) * n), 0);
}

INSTANTIATE_TEST_SUITE_P(AllSolvers, LinearSolverTest,
                         ::testing::Values(LinearSolverType::kAuto,
                                           LinearSolverType::kCholmodSupernodal,
                                           LinearSolverType::kCholmodSimplicial,
                                           LinearSolverType::kEigenLDLT),
                         [](const auto& info) {
                             std::string name = to_string(info.param);
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

}  // namespace
}  // namespace sa
