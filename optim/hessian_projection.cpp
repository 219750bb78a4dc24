#include "optim/hessian_projection.h"

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

namespace detail {

bool project_large_block_by_eigenvalues(double* h, int n, ProjectionMode mode, double epsilon) {
    Eigen::Map<Eigen::MatrixXd> block(h, n, n);
    Eigen::MatrixXd copy = block;
    const bool changed = project_by_eigenvalues(copy, mode, epsilon);
    if (changed) block = copy;
    return changed;
}

}  // namespace detail

}  // namespace sa
