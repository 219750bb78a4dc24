#include "optim/detail/supernodal_solve.h"

#include <cholmod.h>
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <Eigen/CholmodSupport>
#include <cstring>

#include "optim/errors.h"

namespace sa {
namespace {

// Lower triangle of the 5-point Laplacian of an nx x ny grid plus I.
Eigen::SparseMatrix<double> grid_laplacian_lower(int nx, int ny) {
    std::vector<Eigen::Triplet<double>> entries;
    auto id = [nx](int i, int j) { return j * nx + i; };
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            entries.emplace_back(id(i, j), id(i, j), 5.0);
            if (i + 1 < nx) entries.emplace_back(id(i + 1, j), id(i, j), -1.0);
            if (j + 1 < ny) entries.emplace_back(id(i, j + 1), id(i, j), -1.0);
        }
    }
    Eigen::SparseMatrix<double> m(nx * ny, nx * ny);
    m.setFromTriplets(entries.begin(), entries.end());
    return m;
}

// CHOLMOD's supernodal factor of a matrix in its own (postordered) ordering, as the linear
// solver hands it over.
class CholmodFactor {
  public:
    explicit CholmodFactor(Eigen::SparseMatrix<double> lower) : lower_(std::move(lower)) {
        cholmod_start(&common_);
        common_.print = 0;
        common_.supernodal = CHOLMOD_SUPERNODAL;
        cholmod_sparse a = Eigen::viewAsCholmod(lower_);
        a.stype = -1;  // the lower triangle of a symmetric matrix
        factor_ = cholmod_analyze(&a, &common_);
        cholmod_factorize(&a, factor_, &common_);
    }
    ~CholmodFactor() {
        cholmod_free_factor(&factor_, &common_);
        cholmod_finish(&common_);
    }
    CholmodFactor(const CholmodFactor&) = delete;
    CholmodFactor& operator=(const CholmodFactor&) = delete;

    bool ok() const {
        return factor_ != nullptr && factor_->is_super && common_.status == CHOLMOD_OK;
    }
    SupernodalStructure structure() const {
        return {static_cast<int>(factor_->n),
                static_cast<int>(factor_->nsuper),
                static_cast<const int*>(factor_->super),
                static_cast<const int*>(factor_->pi),
                static_cast<const int*>(factor_->px),
                static_cast<const int*>(factor_->s)};
    }
    const double* values() const { return static_cast<const double*>(factor_->x); }
    /// Row k of the factored matrix is row perm[k] of the input.
    const int* perm() const { return static_cast<const int*>(factor_->Perm); }
    const Eigen::SparseMatrix<double>& lower() const { return lower_; }

  private:
    Eigen::SparseMatrix<double> lower_;
    cholmod_common common_{};
    cholmod_factor* factor_ = nullptr;
};

// Solves A x = b through the factor of P A P^T with the plan, on `threads` threads.
Eigen::VectorXd solve(const CholmodFactor& f, const SupernodalSolve& plan, const Eigen::VectorXd& b,
                      int threads) {
    const Eigen::Index n = b.size();
    Eigen::VectorXd permuted(n), x(n);
    for (Eigen::Index k = 0; k < n; ++k) permuted[k] = b[f.perm()[k]];
    tbb::task_arena(threads).execute([&] { plan.solve_in_place(f.values(), permuted.data()); });
    for (Eigen::Index k = 0; k < n; ++k) x[f.perm()[k]] = permuted[k];
    return x;
}

TEST(SupernodalSolve, SplitsAMeshSizedTreeAndSolves) {
    const CholmodFactor f(grid_laplacian_lower(120, 90));
    ASSERT_TRUE(f.ok());
    const SupernodalSolve plan(f.structure());
    EXPECT_LT(plan.serial_share(), 0.3) << "the tree of a grid splits into two halves";
    const Eigen::SparseMatrix<double> full = f.lower().selfadjointView<Eigen::Lower>();
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(full.rows(), -2.0, 3.0).array().sin();
    const Eigen::VectorXd x = solve(f, plan, b, 2);
    EXPECT_LT((full * x - b).norm() / b.norm(), 1e-12);
}

TEST(SupernodalSolve, SameBitsOnOneAndTwoThreads) {
    const CholmodFactor f(grid_laplacian_lower(100, 100));
    ASSERT_TRUE(f.ok());
    const SupernodalSolve plan(f.structure());
    ASSERT_LT(plan.serial_share(), 1.0);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(10000, 1.0, -4.0).array().cos();
    const Eigen::VectorXd one = solve(f, plan, b, 1), two = solve(f, plan, b, 2);
    EXPECT_EQ(std::memcmp(one.data(), two.data(), sizeof(double) * one.size()), 0);
}

TEST(SupernodalSolve, SmallFactorsStaySerial) {
    const CholmodFactor f(grid_laplacian_lower(12, 10));
    ASSERT_TRUE(f.ok());
    const SupernodalSolve plan(f.structure());
    EXPECT_EQ(plan.serial_share(), 1.0);
    const Eigen::SparseMatrix<double> full = f.lower().selfadjointView<Eigen::Lower>();
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(full.rows(), 0.5, 1.5);
    EXPECT_LT((full * solve(f, plan, b, 2) - b).norm() / b.norm(), 1e-12);
}

TEST(SupernodalSolve, RejectsAMalformedStructure) {
    const int first_column[] = {0, 2}, row_start[] = {0, 1}, value_start[] = {0, 2}, rows[] = {0};
    // One supernode of two columns but a single row.
    EXPECT_THROW(SupernodalSolve({2, 1, first_column, row_start, value_start, rows}),
                 InvalidArgumentError);
    EXPECT_THROW(SupernodalSolve({2, 1, nullptr, row_start, value_start, rows}),
                 InvalidArgumentError);
}

}  // namespace
}  // namespace sa
