#include "optim/linear_solver.h"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <new>
#include <optional>
#include <type_traits>
#include <vector>

#include <amd.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "optim/detail/supernodal_solve.h"
#include "optim/errors.h"

namespace sa {

std::string to_string(LinearSolverType type) {
    switch (type) {
        case LinearSolverType::kAuto:
            return "auto";
        case LinearSolverType::kCholmodSupernodal:
            return "cholmod-supernodal";
        case LinearSolverType::kCholmodSimplicial:
            return "cholmod-simplicial";
        case LinearSolverType::kEigenLDLT:
            return "eigen-ldlt";
    }
    return "unknown";
}

LinearSolverType parse_linear_solver(const std::string& name) {
    for (LinearSolverType t :
         {LinearSolverType::kAuto, LinearSolverType::kCholmodSupernodal,
          LinearSolverType::kCholmodSimplicial, LinearSolverType::kEigenLDLT}) {
        if (to_string(t) == name) return t;
    }
    throw InvalidArgumentError(
        "unknown linear solver '" + name +
        "' (expected auto, cholmod-supernodal, cholmod-simplicial or eigen-ldlt)");
}

namespace {
using SparseMatrix = Eigen::SparseMatrix<double>;

/// Fill-reducing ordering for Eigen's simplicial factorizations by SuiteSparse's AMD (the one
/// CHOLMOD uses) instead of Eigen's own: the same fill, and an analysis about ten times faster
/// (docs/measurements.md, "Figures moved out of the code"), which matters when every submesh is
/// analyzed once and factored a few times. Eigen hands it the full symmetric pattern.
struct SuiteSparseAmdOrdering {
    template <class Matrix, class Permutation>
    void operator()(const Matrix& symmetric, Permutation& permutation) const {
        static_assert(std::is_same_v<typename Matrix::StorageIndex, int>, "amd_order takes int");
        const int n = static_cast<int>(symmetric.cols());
        std::vector<int> order(n);  // order[k]: the k-th pivot
        const int status = amd_order(n, symmetric.outerIndexPtr(), symmetric.innerIndexPtr(),
                                     order.data(), nullptr, nullptr);
        if (status == AMD_OUT_OF_MEMORY) throw std::bad_alloc();
        if (status < AMD_OK) {
            throw InvalidArgumentError("linear solver: AMD rejected the matrix pattern (status " +
                                       std::to_string(status) + ")");
        }
        permutation.resize(n);
        for (int k = 0; k < n; ++k) permutation.indices()(k) = order[k];
    }
};

/// Eigen's supernodal LL^T with CHOLMOD's factor in reach (for its fill-reducing permutation).
class CholmodSupernodal : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
  public:
    const cholmod_factor* factor() const { return m_cholmodFactor; }

    /// Turns the analyzed factor of A, with its permutation P, into that of P A P^T with the
    /// natural ordering: L's structure already describes P A P^T (L is always the factor of the
    /// permuted matrix), so only the permutation is reset to the identity.
    void keep_structure_for_permuted_matrix() {
        cholmod_factor* L = m_cholmodFactor;
        int* perm = static_cast<int*>(L->Perm);
        for (std::size_t k = 0; k < L->n; ++k) perm[k] = static_cast<int>(k);
        if (L->IPerm != nullptr) {
            int* inverse = static_cast<int*>(L->IPerm);
            for (std::size_t k = 0; k < L->n; ++k) inverse[k] = static_cast<int>(k);
        }
        L->ordering = CHOLMOD_NATURAL;
    }
};
using CholmodSimplicial = Eigen::CholmodSimplicialLLT<SparseMatrix, Eigen::Lower>;
using EigenLDLT = Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, SuiteSparseAmdOrdering>;

/// CHOLMOD reports through its own printf by default; the library stays silent and reports
/// through statuses instead.
void quiet(cholmod_common& common) {
    common.print = 0;
}

/// Supernodes are merged into larger ones (with some explicit zeros) while they have fewer than
/// 16, 64 or 128 columns (CHOLMOD's defaults: 4, 16, 48; the allowed share of zeros, zrelax, kept
/// at its defaults): fewer and larger BLAS calls, faster per factorization on 3D submeshes, full
/// 3D systems, vertex stages and large grid Laplacians; larger settings and more zeros were
/// slower on all of them (docs/measurements.md, "Figures moved out of the code").
void relax_supernodes(cholmod_common& common) {
    common.nrelax[0] = 16;
    common.nrelax[1] = 64;
    common.nrelax[2] = 128;
}

/// The matrix P A P^T for a fixed fill-reducing permutation P, filled by a fixed gather of A's
/// values, for the supernodal factor of A's analysis turned into that of P A P^T with the natural
/// ordering (CholmodSupernodal::keep_structure_for_permuted_matrix). Given A's lower triangle and
/// a permutation, cholmod_factorize transposes the matrix twice at every call (triu(PAP'), then
/// its transpose: a visible share of a 3D full solve's profile); given the
/// lower triangle of an already permuted matrix with the natural ordering it factors the matrix
/// as it is. The solves permute the right-hand sides and solutions.
struct PrepermutedMatrix {
    SparseMatrix permuted;    ///< lower triangle of P A P^T
    std::vector<int> source;  ///< entry p of `permuted` <- entry source[p] of A
    std::vector<int> pivot;   ///< pivot[k] = the row of A that is row k of P A P^T
    /// For one right-hand side; kept only when it splits the tree (CHOLMOD's single-thread
    /// substitutions are otherwise as fast or faster, as on factors of thousands of small
    /// supernodes). Per Newton iteration, the split against CHOLMOD's: docs/measurements.md,
    /// "Triangular solves alone" and "Figures moved out of the code".
    std::optional<SupernodalSolve> substitution;

    /// The pattern of P A P^T, from A's analyzed supernodal factor (its permutation, and its
    /// structure for the substitutions).
    PrepermutedMatrix(const SparseMatrix& lower, const cholmod_factor& factor) {
        const int n = static_cast<int>(lower.cols());
        const int* order = static_cast<const int*>(factor.Perm);
        pivot.assign(order, order + n);
        std::vector<int> position(n);
        for (int k = 0; k < n; ++k) position[pivot[k]] = k;
        // Entry (i, j) of A goes to (max, min) of (position[i], position[j]): count per column,
        // then place the entries of each new column in row order. Entries above the diagonal
        // are ignored, as CHOLMOD ignores them in a lower-triangle matrix.
        const int* outer = lower.outerIndexPtr();
        const int* rows = lower.innerIndexPtr();
        std::vector<int> begin(n + 1, 0);
        for (int j = 0; j < n; ++j) {
            for (int p = outer[j]; p < outer[j + 1]; ++p) {
                if (rows[p] >= j) ++begin[std::min(position[rows[p]], position[j]) + 1];
            }
        }
        for (int j = 0; j < n; ++j) begin[j + 1] += begin[j];
        std::vector<std::pair<int, int>> entries(begin[n]);  // (new row, entry of A)
        {
            std::vector<int> cursor(begin.begin(), begin.end() - 1);
            for (int j = 0; j < n; ++j) {
                for (int p = outer[j]; p < outer[j + 1]; ++p) {
                    if (rows[p] < j) continue;
                    const int a = position[rows[p]], b = position[j];
                    entries[cursor[std::min(a, b)]++] = {std::max(a, b), p};
                }
            }
        }
        permuted.resize(n, n);
        permuted.resizeNonZeros(static_cast<Eigen::Index>(entries.size()));
        source.resize(entries.size());
        for (int j = 0; j < n; ++j) {
            permuted.outerIndexPtr()[j] = begin[j];
            std::sort(entries.begin() + begin[j], entries.begin() + begin[j + 1]);
            for (int p = begin[j]; p < begin[j + 1]; ++p) {
                permuted.innerIndexPtr()[p] = entries[p].first;
                source[p] = entries[p].second;
            }
        }
        permuted.outerIndexPtr()[n] = begin[n];
        if (factor.is_super) {
            substitution.emplace(SupernodalStructure{
                n, static_cast<int>(factor.nsuper), static_cast<const int*>(factor.super),
                static_cast<const int*>(factor.pi), static_cast<const int*>(factor.px),
                static_cast<const int*>(factor.s)});
            if (substitution->serial_share() >= 1.0) substitution.reset();
        }
    }

    /// A gather (sequential writes) on the threads of the caller's arena: a serial scatter by
    /// entry of A is a visible share of a large full system's run.
    void fill(const SparseMatrix& lower) {
        const double* from = lower.valuePtr();
        double* to = permuted.valuePtr();
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, source.size(), 1 << 14),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                              for (std::size_t p = range.begin(); p != range.end(); ++p)
                                  to[p] = from[source[p]];
                          });
    }

    /// One right-hand side: the two substitutions by SupernodalSolve, on the caller's threads.
    Eigen::VectorXd solve(const CholmodSupernodal& solver, const Eigen::VectorXd& rhs) const {
        Eigen::VectorXd b(rhs.size());
        for (Eigen::Index k = 0; k < rhs.size(); ++k) b[k] = rhs[pivot[k]];
        substitution->solve_in_place(static_cast<const double*>(solver.factor()->x), b.data());
        Eigen::VectorXd x(rhs.size());
        for (Eigen::Index k = 0; k < rhs.size(); ++k) x[pivot[k]] = b[k];
        return x;
    }

    /// Several right-hand sides: CHOLMOD's level-3 substitutions.
    Eigen::MatrixXd solve(const CholmodSupernodal& solver, const Eigen::MatrixXd& rhs) const {
        Eigen::MatrixXd b(rhs.rows(), rhs.cols());
        for (Eigen::Index k = 0; k < rhs.rows(); ++k) b.row(k) = rhs.row(pivot[k]);
        const Eigen::MatrixXd y = solver.solve(b);
        Eigen::MatrixXd x(rhs.rows(), rhs.cols());
        for (Eigen::Index k = 0; k < rhs.rows(); ++k) x.row(pivot[k]) = y.row(k);
        return x;
    }
};

void set_ordering(cholmod_common& common, FillOrdering ordering) {
    if (ordering == FillOrdering::kAmd) {
        common.nmethods = 1;
        common.method[0].ordering = CHOLMOD_AMD;
    }
}
}  // namespace

struct LinearSolver::Impl {
    LinearSolverType requested;
    LinearSolverType type;
    FillOrdering ordering = FillOrdering::kBest;
    std::optional<CholmodSupernodal> supernodal;
    std::optional<PrepermutedMatrix> prepermuted;  ///< what `supernodal` factors, when set
    std::optional<CholmodSimplicial> simplicial;
    std::optional<EigenLDLT> ldlt;
    std::string fallback_reason;
    bool analyzed = false;

    void make(LinearSolverType t) {
        type = t;
        supernodal.reset();
        prepermuted.reset();
        simplicial.reset();
        ldlt.reset();
        switch (t) {
            case LinearSolverType::kCholmodSupernodal:
                quiet(supernodal.emplace().cholmod());
                // A single factorization (kAmd) keeps CHOLMOD's default merging: as fast once,
                // and a smaller factor (about 40% fewer stored entries on the real form of a planar
                // LSCM system of a million unknowns), which matters where fresh memory is slow to
                // touch (docs/measurements.md, "Planar parameterization at scale").
                if (ordering != FillOrdering::kAmd) relax_supernodes(supernodal->cholmod());
                set_ordering(supernodal->cholmod(), ordering);
                break;
            case LinearSolverType::kCholmodSimplicial:
                quiet(simplicial.emplace().cholmod());
                set_ordering(simplicial->cholmod(), ordering);
                break;
            case LinearSolverType::kEigenLDLT:
                ldlt.emplace();
                break;
            case LinearSolverType::kAuto:
                break;  // chosen by analyze(), from CHOLMOD's flop count
        }
    }

    /// Factors `input` (A itself, or the permuted copy of PrepermutedMatrix) with `solver`;
    /// `lower` is A, for the fallback.
    template <class Cholmod>
    FactorizationStatus factorize_cholmod(Cholmod& solver, const SparseMatrix& input,
                                          const SparseMatrix& lower) {
        solver.factorize(input);
        const int status = solver.cholmod().status;
        if (solver.info() == Eigen::Success && status >= CHOLMOD_OK)
            return FactorizationStatus::kSuccess;
        if (status == CHOLMOD_NOT_POSDEF ||
            (status >= CHOLMOD_OK && solver.info() != Eigen::Success)) {
            return FactorizationStatus::kNotPositiveDefinite;
        }
        fallback_reason = "CHOLMOD status " + std::to_string(status) + " (" +
                          (status == CHOLMOD_OUT_OF_MEMORY ? "out of memory"
                           : status == CHOLMOD_TOO_LARGE   ? "problem too large"
                                                           : "error") +
                          "); using Eigen's SimplicialLDLT";
        make(LinearSolverType::kEigenLDLT);
        ldlt->analyzePattern(lower);
        return factorize_ldlt(lower);
    }

    FactorizationStatus factorize_ldlt(const SparseMatrix& lower) {
        ldlt->factorize(lower);
        if (ldlt->info() == Eigen::NumericalIssue) return FactorizationStatus::kNotPositiveDefinite;
        if (ldlt->info() != Eigen::Success) return FactorizationStatus::kFailed;
        // LDL^T succeeds on indefinite matrices: positive definite means every pivot > 0.
        if (lower.rows() > 0 && !(ldlt->vectorD().minCoeff() > 0.0)) {
            return FactorizationStatus::kNotPositiveDefinite;
        }
        return FactorizationStatus::kSuccess;
    }
};

LinearSolver::LinearSolver(LinearSolverType type, FillOrdering ordering)
    : impl_(std::make_unique<Impl>()) {
    impl_->requested = type;
    impl_->ordering = ordering;
    impl_->make(type);
}
LinearSolver::~LinearSolver() = default;
LinearSolver::LinearSolver(LinearSolver&&) noexcept = default;
LinearSolver& LinearSolver::operator=(LinearSolver&&) noexcept = default;

void LinearSolver::analyze(const SparseMatrix& lower) {
    if (lower.rows() != lower.cols()) {
        throw InvalidArgumentError("linear solver: matrix is " + std::to_string(lower.rows()) +
                                   " x " + std::to_string(lower.cols()) + ", not square");
    }
    // A fresh supernodal solver: the last analysis may have replaced it by a prepermuted one.
    if (impl_->requested == LinearSolverType::kAuto ||
        impl_->type == LinearSolverType::kCholmodSupernodal)
        impl_->make(LinearSolverType::kCholmodSupernodal);
    switch (impl_->type) {
        case LinearSolverType::kCholmodSupernodal:
            impl_->supernodal->analyzePattern(lower);
            if (impl_->requested == LinearSolverType::kAuto &&
                impl_->supernodal->cholmod().fl < kAutoSupernodalFlops) {
                impl_->make(LinearSolverType::kEigenLDLT);
                impl_->ldlt->analyzePattern(lower);
            } else if (impl_->ordering == FillOrdering::kBest &&
                       impl_->supernodal->info() == Eigen::Success &&
                       impl_->supernodal->factor() != nullptr && lower.cols() > 0) {
                // Factored many times (a Newton solve): permute once, factor in place.
                impl_->prepermuted.emplace(lower, *impl_->supernodal->factor());
                impl_->supernodal->keep_structure_for_permuted_matrix();
            }
            break;
        case LinearSolverType::kCholmodSimplicial:
            impl_->simplicial->analyzePattern(lower);
            break;
        case LinearSolverType::kEigenLDLT:
            impl_->ldlt->analyzePattern(lower);
            break;
        case LinearSolverType::kAuto:
            break;  // replaced above
    }
    impl_->analyzed = true;
}

FactorizationStatus LinearSolver::factorize(const SparseMatrix& lower) {
    if (!impl_->analyzed) throw InvalidArgumentError("linear solver: factorize before analyze");
    switch (impl_->type) {
        case LinearSolverType::kCholmodSupernodal:
            if (impl_->prepermuted) {
                impl_->prepermuted->fill(lower);
                return impl_->factorize_cholmod(*impl_->supernodal, impl_->prepermuted->permuted,
                                                lower);
            }
            return impl_->factorize_cholmod(*impl_->supernodal, lower, lower);
        case LinearSolverType::kCholmodSimplicial:
            return impl_->factorize_cholmod(*impl_->simplicial, lower, lower);
        case LinearSolverType::kEigenLDLT:
            return impl_->factorize_ldlt(lower);
        case LinearSolverType::kAuto:
            break;
    }
    return FactorizationStatus::kFailed;
}

Eigen::VectorXd LinearSolver::solve(const Eigen::VectorXd& rhs) const {
    if (impl_->type == LinearSolverType::kCholmodSupernodal && impl_->prepermuted &&
        impl_->prepermuted->substitution) {
        return impl_->prepermuted->solve(*impl_->supernodal, rhs);
    }
    return solve_columns(rhs);
}

Eigen::MatrixXd LinearSolver::solve_columns(const Eigen::MatrixXd& rhs) const {
    switch (impl_->type) {
        case LinearSolverType::kCholmodSupernodal:
            if (impl_->prepermuted) return impl_->prepermuted->solve(*impl_->supernodal, rhs);
            return impl_->supernodal->solve(rhs);
        case LinearSolverType::kCholmodSimplicial:
            return impl_->simplicial->solve(rhs);
        case LinearSolverType::kEigenLDLT:
            return impl_->ldlt->solve(rhs);
        case LinearSolverType::kAuto:
            break;
    }
    return {};
}

LinearSolverType LinearSolver::active_type() const {
    return impl_->type;
}
const std::string& LinearSolver::fallback_reason() const {
    return impl_->fallback_reason;
}

}  // namespace sa
