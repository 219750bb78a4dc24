#include "optim/hessian_projection.h"

#include <Eigen/Eigenvalues>

#include "optim/errors.h"

namespace sa {

std::string to_string(ProjectionMode mode) {
    switch (mode) {
        case ProjectionMode::kClamp:
            return "clamp";
        case ProjectionMode::kAbs:
            return "abs";
        case ProjectionMode::kShift:
            return "shift";
        case ProjectionMode::kNone:
            return "none";
    }
    return "unknown";
}

ProjectionMode parse_projection(const std::string& name) {
    for (ProjectionMode mode : {ProjectionMode::kClamp, ProjectionMode::kAbs,
                                ProjectionMode::kShift, ProjectionMode::kNone}) {
        if (to_string(mode) == name) return mode;
    }
    throw InvalidArgumentError("unknown projection '" + name +
                               "' (expected clamp, abs, shift or none)");
}

namespace {

/// Eigenvalues of the symmetric `h` clamped (or mirrored) to epsilon, or shifted, in place.
template <class Matrix>
bool project_symmetric(Matrix& h, ProjectionMode mode, double epsilon) {
    if (mode == ProjectionMode::kShift) {
        Eigen::SelfAdjointEigenSolver<Matrix> eig(h, Eigen::EigenvaluesOnly);
        const double smallest = eig.eigenvalues()(0);
        if (smallest >= epsilon) return false;
        h.diagonal().array() += epsilon - smallest;
        return true;
    }
    Eigen::SelfAdjointEigenSolver<Matrix> eig(h);
    typename Eigen::SelfAdjointEigenSolver<Matrix>::RealVectorType values = eig.eigenvalues();
    bool changed = false;
    for (Eigen::Index i = 0; i < values.size(); ++i) {
        double v = mode == ProjectionMode::kAbs ? std::abs(values(i)) : values(i);
        v = std::max(v, epsilon);
        changed |= v != values(i);
        values(i) = v;
    }
    if (changed) h = eig.eigenvectors() * values.asDiagonal() * eig.eigenvectors().transpose();
    return changed;
}

/// A matrix of up to kLargestStackProjection rows and columns, on the stack.
using StackMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor,
                                  kLargestStackProjection, kLargestStackProjection>;

/// project_symmetric() on `h` through a copy of type Matrix: contiguous storage, where `h` may
/// be a view with an outer stride.
template <class Matrix>
bool project_copy(MatrixRef h, ProjectionMode mode, double epsilon) {
    Matrix copy = h;
    const bool changed = project_symmetric(copy, mode, epsilon);
    if (changed) h = copy;
    return changed;
}

}  // namespace

bool project_hessian_block(MatrixRef h, ProjectionMode mode, double epsilon) {
    if (mode == ProjectionMode::kNone) return false;
    if (is_diagonally_dominant_above(h, epsilon)) return false;
    if (!h.allFinite()) return false;
    return h.rows() <= kLargestStackProjection ? project_copy<StackMatrix>(h, mode, epsilon)
                                               : project_copy<Eigen::MatrixXd>(h, mode, epsilon);
}

namespace detail {

template <int N>
bool project_by_eigenvalues(Mat<N>& h, ProjectionMode mode, double epsilon) {
    return project_symmetric(h, mode, epsilon);
}

bool project_small_block_by_eigenvalues(double* h, int n, ProjectionMode mode, double epsilon) {
    return project_copy<StackMatrix>(Eigen::Map<Eigen::MatrixXd>(h, n, n), mode, epsilon);
}

}  // namespace detail

static_assert(kLargestFixedSizeProjection == 4, "instantiate every size up to it below");
#define SA_PROJECT_BY_EIGENVALUES(N) \
    template bool detail::project_by_eigenvalues<N>(Mat<N>&, ProjectionMode, double);
SA_PROJECT_BY_EIGENVALUES(1)
SA_PROJECT_BY_EIGENVALUES(2)
SA_PROJECT_BY_EIGENVALUES(3)
SA_PROJECT_BY_EIGENVALUES(4)
#undef SA_PROJECT_BY_EIGENVALUES

}  // namespace sa
