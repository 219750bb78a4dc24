#pragma once
// Sparse symmetric positive-definite solver for the Newton system H d = -g, given H's lower
// triangle. CHOLMOD stays behind this interface: cholmod.h is not included by any public header.
//
//   kCholmodSupernodal   CHOLMOD supernodal LL^T (BLAS-3 on dense supernodes, OpenBLAS);
//                        the default, and the fastest on meshes beyond a few thousand elements.
//   kCholmodSimplicial   CHOLMOD simplicial LL^T: no BLAS; fast on small systems.
//   kEigenLDLT           Eigen's SimplicialLDLT, ordered by SuiteSparse's AMD (the analysis is ten
//                        times faster than with Eigen's own AMD, for the same fill).
//   kAuto                kEigenLDLT when CHOLMOD's analysis counts fewer than kAutoSupernodalFlops
//                        for the factorization (the supernodes are then too small for BLAS-3 to
//                        pay), kCholmodSupernodal otherwise: the crossing point of the two on
//                        systems from 7.9e5 to 3.6e8 flops (docs/measurements.md, "Figures moved
//                        out of the code").
// The symbolic analysis (fill-reducing ordering) is done by analyze() and reused by every
// factorize() until analyze() is called again. CHOLMOD's ordering is chosen by FillOrdering:
//   kBest   CHOLMOD's default: AMD, then METIS when AMD's fill is large, the better kept. Pays off
//           when the pattern is factored many times (a Newton solve). The supernodal solver then
//           also permutes the pattern once and factors P A P^T in place with a fixed gather of
//           the values, where cholmod_factorize would transpose the matrix twice per call; the
//           factor of A's analysis serves P A P^T with its permutation reset, so nothing is
//           analyzed twice.
//   kAmd    AMD alone: analysis several times faster on large meshes for somewhat more fill; for
//           a single factorization.
// (Measurements of each choice: docs/measurements.md, "Figures moved out of the code".)
//
// CHOLMOD's OpenMP regions run as the process's OpenMP runtime runs them (the sa command runs
// them serially: frontends/cli/serial_openmp.h). If CHOLMOD fails for a reason other than an
// indefinite matrix (out of memory, a problem too large), the solver falls back to Eigen's
// SimplicialLDLT and says so in fallback_reason().

#include <Eigen/SparseCore>
#include <memory>
#include <string>

#include "optim/linear_solver_type.h"

namespace sa {

enum class FactorizationStatus {
    kSuccess,
    kNotPositiveDefinite,  ///< the matrix (as regularized so far) is not positive definite
    kFailed,               ///< every available factorization failed for another reason
};

class LinearSolver {
  public:
    explicit LinearSolver(LinearSolverType type = LinearSolverType::kCholmodSupernodal,
                          FillOrdering ordering = FillOrdering::kBest);
    ~LinearSolver();
    LinearSolver(LinearSolver&&) noexcept;
    LinearSolver& operator=(LinearSolver&&) noexcept;

    /// Symbolic analysis of the pattern of `lower` (a square lower triangle, column-major).
    void analyze(const Eigen::SparseMatrix<double>& lower);
    /// Numeric factorization of `lower`, whose pattern must be the analyzed one.
    FactorizationStatus factorize(const Eigen::SparseMatrix<double>& lower);
    /// Solves with the last successful factorization. With the supernodal factorization of a
    /// Newton solve (FillOrdering::kBest), when its elimination tree splits, the substitutions
    /// run on two threads of the caller's TBB arena (optim/detail/supernodal_solve.h), with the
    /// same result on any thread count. Not for concurrent calls on one solver (neither are
    /// CHOLMOD's own solves).
    Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;
    /// The same for several right-hand sides at once (one column each; level-3 BLAS).
    Eigen::MatrixXd solve_columns(const Eigen::MatrixXd& rhs) const;

    /// The factorization actually in use (differs from the requested one after a fallback).
    LinearSolverType active_type() const;
    /// Why the solver fell back to Eigen's LDL^T; empty if it did not.
    const std::string& fallback_reason() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace sa
