#include "optim/hermitian_solve.h"

#include <Eigen/CholmodSupport>
#include <string>

#include "optim/errors.h"

namespace sa {

std::optional<Eigen::VectorXcd> solve_hermitian_positive_definite(
    const Eigen::SparseMatrix<std::complex<double>>& lower, const Eigen::VectorXcd& rhs) {
    if (lower.rows() != lower.cols() || lower.rows() != rhs.size()) {
        throw InvalidArgumentError("hermitian solve: matrix is " + std::to_string(lower.rows()) +
                                   " x " + std::to_string(lower.cols()) + ", right-hand side " +
                                   std::to_string(rhs.size()));
    }
    if (lower.rows() == 0) return Eigen::VectorXcd();
    Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<std::complex<double>>, Eigen::Lower> llt;
    llt.cholmod().print = 0;  // statuses, not CHOLMOD's printf
    // AMD alone: one factorization does not repay METIS's slower analysis.
    llt.cholmod().nmethods = 1;
    llt.cholmod().method[0].ordering = CHOLMOD_AMD;
    llt.compute(lower);
    if (llt.info() != Eigen::Success) return std::nullopt;
    return Eigen::VectorXcd(llt.solve(rhs));
}

}  // namespace sa
