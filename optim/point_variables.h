#pragma once
// Variables of points (mesh vertices) without hand-built flat indices.
//
// A problem over the positions of #V points in D dimensions keeps them point after point:
// coordinate k of point v is variable offset + D v + k. These helpers build that vector from a
// #V x D matrix and back, give a point's D variable indices, and give each simplex's variables
// (its K points' coordinates, point after point) as the elements of a term:
//
//   sa::Problem problem(sa::flatten_points(V));                 // V #V x 2
//   const auto triangles = sa::simplex_variables<2, 3>(F);      // F #F x 3: {x0 y0 x1 y1 x2 y2}
//   problem.add_elements<6>("area", triangles, [&](auto const& x, sa::Index f) {
//       const auto a = sa::point<2>(x, 0), b = sa::point<2>(x, 1), c = sa::point<2>(x, 2);
//       ...
//   });
//   problem.set_fixed(sa::point_variables<2>(v));                // pin vertex v
//   const Eigen::MatrixXd result = sa::unflatten_points<2>(problem.variables());

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "optim/errors.h"
#include "optim/types.h"

namespace sa {

/// The points' coordinates, point after point: #V x D -> D #V values.
inline Eigen::VectorXd flatten_points(const Eigen::MatrixXd& points) {
    Eigen::VectorXd x(points.size());
    for (Eigen::Index v = 0; v < points.rows(); ++v)
        x.segment(v * points.cols(), points.cols()) = points.row(v).transpose();
    return x;
}

/// The inverse of flatten_points: `count` points (all that fit when -1) of D coordinates from
/// variable `offset` on, as a count x D matrix. Throws InvalidArgumentError when they do not fit.
template <int D>
Eigen::MatrixXd unflatten_points(const Eigen::VectorXd& x, Index offset = 0, Index count = -1) {
    static_assert(D > 0);
    if (count < 0) count = offset <= x.size() ? (Index(x.size()) - offset) / D : 0;
    if (offset < 0 || offset + Eigen::Index(count) * D > x.size()) {
        throw InvalidArgumentError("unflatten_points: " + std::to_string(count) + " points of " +
                                   std::to_string(D) + " from variable " + std::to_string(offset) +
                                   " do not fit in " + std::to_string(x.size()) + " variables");
    }
    Eigen::MatrixXd points(count, D);
    for (Index v = 0; v < count; ++v) points.row(v) = x.segment<D>(offset + D * v).transpose();
    return points;
}

/// The D variable indices of point `v`: {offset + D v, ..., offset + D v + D - 1}.
template <int D>
std::array<Index, D> point_variables(Index v, Index offset = 0) {
    static_assert(D > 0);
    std::array<Index, D> variables;
    for (int k = 0; k < D; ++k) variables[k] = offset + D * v + k;
    return variables;
}

/// The elements of a term over simplices: for each row of `simplices` (#S x K point indices), the
/// K D variables of its points, point after point. Throws InvalidArgumentError when `simplices`
/// does not have K columns or names a negative point.
template <int D, int K>
std::vector<std::array<Index, K * D>> simplex_variables(const Eigen::MatrixXi& simplices,
                                                        Index offset = 0) {
    static_assert(D > 0 && K > 0);
    if (simplices.cols() != K) {
        throw InvalidArgumentError("simplex_variables: expected " + std::to_string(K) +
                                   " points per simplex, got a #S x " +
                                   std::to_string(simplices.cols()) + " matrix");
    }
    std::vector<std::array<Index, K * D>> elements(simplices.rows());
    for (Eigen::Index s = 0; s < simplices.rows(); ++s) {
        for (int j = 0; j < K; ++j) {
            if (simplices(s, j) < 0) {
                throw InvalidArgumentError("simplex_variables: simplex " + std::to_string(s) +
                                           " names point " + std::to_string(simplices(s, j)));
            }
            for (int k = 0; k < D; ++k) elements[s][D * j + k] = offset + D * simplices(s, j) + k;
        }
    }
    return elements;
}

/// Inside an element function: the D coordinates of the element's j-th point (a view into x).
template <int D, class Vector>
auto point(const Vector& x, int j) {
    return x.template segment<D>(D * j);
}

}  // namespace sa
