#include "frontends/polycube/polycube_constraints.h"

#include <cmath>

namespace sa {

namespace {

void check_axis(int axis, const char* who) {
    if (axis < 0 || axis > 2) {
        throw InvalidArgumentError(std::string(who) + ": axis " + std::to_string(axis) +
                                   " outside 0..2");
    }
}

template <int R>
void check_axes(const std::array<int, R>& axes, const char* who) {
    for (int k = 0; k < R; ++k) {
        check_axis(axes[k], who);
        for (int j = 0; j < k; ++j) {
            if (axes[j] == axes[k]) {
                throw InvalidArgumentError(std::string(who) + ": axis " + std::to_string(axes[k]) +
                                           " given twice");
            }
        }
    }
}

}  // namespace

LinearConstraintRows<9, 2> planarity_rows(int axis, const Eigen::Matrix<double, 3, 2>& edges) {
    check_axis(axis, "planarity_rows");
    LinearConstraintRows<9, 2> rows;
    for (int k = 0; k < 2; ++k) {
        const double length = edges.col(k).norm();
        if (!(length > 0.0) || !std::isfinite(length)) {
            throw InvalidArgumentError("planarity_rows: edge " + std::to_string(k) +
                                       " has length " + std::to_string(length));
        }
        // a^T A e = sum_j A(axis, j) e_j, and A(axis, j) is vec(A)[3 j + axis].
        for (int j = 0; j < 3; ++j) rows.coefficients(k, 3 * j + axis) = edges(j, k) / length;
    }
    return rows;
}

LinearConstraintRows<9, 2> planarity_vertex_rows(int axis, const std::array<double, 2>& lengths) {
    check_axis(axis, "planarity_vertex_rows");
    LinearConstraintRows<9, 2> rows;
    for (int k = 0; k < 2; ++k) {
        if (!(lengths[k] > 0.0) || !std::isfinite(lengths[k])) {
            throw InvalidArgumentError("planarity_vertex_rows: edge " + std::to_string(k) +
                                       " has length " + std::to_string(lengths[k]));
        }
        rows.coefficients(k, axis) = -1.0 / lengths[k];
        rows.coefficients(k, 3 * (k + 1) + axis) = 1.0 / lengths[k];
    }
    return rows;
}

template <int R>
LinearConstraintRows<12, R> sliding_rows(const Eigen::Vector3d& rest_point,
                                         const std::array<int, R>& axes,
                                         const std::array<double, R>& coordinates) {
    check_axes<R>(axes, "sliding_rows");
    LinearConstraintRows<12, R> rows;
    for (int k = 0; k < R; ++k) {
        for (int j = 0; j < 3; ++j) rows.coefficients(k, 3 * j + axes[k]) = rest_point[j];
        rows.coefficients(k, 9 + axes[k]) = 1.0;
        rows.rhs[k] = coordinates[k];
    }
    return rows;
}

template <int R>
LinearConstraintRows<3, R> sliding_vertex_rows(const std::array<int, R>& axes,
                                               const std::array<double, R>& coordinates) {
    check_axes<R>(axes, "sliding_vertex_rows");
    LinearConstraintRows<3, R> rows;
    for (int k = 0; k < R; ++k) {
        rows.coefficients(k, axes[k]) = 1.0;
        rows.rhs[k] = coordinates[k];
    }
    return rows;
}

template LinearConstraintRows<12, 1> sliding_rows<1>(const Eigen::Vector3d&,
                                                     const std::array<int, 1>&,
                                                     const std::array<double, 1>&);
template LinearConstraintRows<12, 2> sliding_rows<2>(const Eigen::Vector3d&,
                                                     const std::array<int, 2>&,
                                                     const std::array<double, 2>&);
template LinearConstraintRows<12, 3> sliding_rows<3>(const Eigen::Vector3d&,
                                                     const std::array<int, 3>&,
                                                     const std::array<double, 3>&);
template LinearConstraintRows<3, 1> sliding_vertex_rows<1>(const std::array<int, 1>&,
                                                           const std::array<double, 1>&);
template LinearConstraintRows<3, 2> sliding_vertex_rows<2>(const std::array<int, 2>&,
                                                           const std::array<double, 2>&);
template LinearConstraintRows<3, 3> sliding_vertex_rows<3>(const std::array<int, 3>&,
                                                           const std::array<double, 3>&);

}  // namespace sa
