#include <gtest/gtest.h>

#include "optim/optim.h"

namespace sa {
namespace {

TEST(PointVariables, FlattenAndUnflattenArePointAfterPoint) {
    Eigen::MatrixXd points(3, 2);
    points << 1, 2, 3, 4, 5, 6;
    const Eigen::VectorXd x = flatten_points(points);
    EXPECT_EQ(x, (Eigen::VectorXd(6) << 1, 2, 3, 4, 5, 6).finished());
    EXPECT_EQ(unflatten_points<2>(x), points);
    EXPECT_EQ(unflatten_points<2>(x, 2, 1), points.row(1));
    EXPECT_THROW(unflatten_points<2>(x, 2, 3), InvalidArgumentError);
    EXPECT_EQ((point_variables<3>(2, 10)), (std::array<Index, 3>{16, 17, 18}));
}

TEST(PointVariables, SimplexVariablesNameEachPointsCoordinates) {
    Eigen::MatrixXi triangles(2, 3);
    triangles << 0, 1, 2, 2, 1, 3;
    const auto elements = simplex_variables<2, 3>(triangles);
    ASSERT_EQ(elements.size(), 2u);
    EXPECT_EQ(elements[1], (std::array<Index, 6>{4, 5, 2, 3, 6, 7}));
    EXPECT_EQ((simplex_variables<3, 3>(triangles, 1)[0]),
              (std::array<Index, 9>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
    EXPECT_THROW((simplex_variables<2, 4>(triangles)), InvalidArgumentError);
    triangles(1, 2) = -1;
    EXPECT_THROW((simplex_variables<2, 3>(triangles)), InvalidArgumentError);
}

TEST(PointVariables, AnElementFunctionReadsItsPointsAndAVertexIsPinnedAtOnce) {
    // Two triangles of a unit square, each pulled towards twice its rest area, vertex 0 pinned.
    Eigen::MatrixXd V(4, 2);
    V << 0, 0, 1, 0, 1, 1, 0, 1;
    Eigen::MatrixXi F(2, 3);
    F << 0, 1, 2, 0, 2, 3;
    Problem problem(flatten_points(V));
    problem.add_elements<6>("area", simplex_variables<2, 3>(F), [](auto const& x, Index) {
        const auto a = point<2>(x, 0), b = point<2>(x, 1), c = point<2>(x, 2);
        const auto area = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
        return (area - 1.0) * (area - 1.0) + 1e-3 * (a.squaredNorm() + b.squaredNorm());
    });
    problem.set_fixed(point_variables<2>(0));
    EXPECT_TRUE(problem.is_fixed(0) && problem.is_fixed(1) && !problem.is_fixed(2));
    ASSERT_TRUE(solve(problem).success());
    const Eigen::MatrixXd result = unflatten_points<2>(problem.variables());
    EXPECT_EQ(result.row(0), V.row(0));
    for (int f = 0; f < 2; ++f) {
        const Eigen::Vector2d a = result.row(F(f, 0)), b = result.row(F(f, 1)),
                              c = result.row(F(f, 2));
        const double area = 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
        EXPECT_NEAR(area, 1.0, 1e-2);
    }
}

}  // namespace
}  // namespace sa
