// PolyCube's linear constraints (polycube_constraints.h) as LinearConstraintEnergy rows.
#include "frontends/polycube/polycube_constraints.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "energies/linear_constraint_energy.h"
#include "optim/derivative_check.h"

namespace sa {
namespace {

Mat<3> rotation(double angle, const Vec<3>& axis) {
    return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// A rest facet in a tetrahedron's frame, mapped by A: the planarity rows vanish exactly when the
// mapped facet is orthogonal to the axis.
TEST(PolycubeConstraints, PlanarityRowsVanishOnAFacetOrthogonalToTheAxis) {
    Eigen::Matrix<double, 3, 2> edges;
    edges << 1.0, 0.3, 0.2, 1.1, -0.4, 0.6;
    const Vec<3> normal = edges.col(0).cross(edges.col(1)).normalized();
    for (int axis = 0; axis < 3; ++axis) {
        const LinearConstraintEnergy<9, 2> energy({planarity_rows(axis, 2.5 * edges)});
        // A rotation taking the facet's normal to the axis, times a scaling in the plane.
        const Mat<3> R =
            Eigen::Quaterniond::FromTwoVectors(normal, Vec<3>::Unit(axis)).toRotationMatrix();
        const Mat<3> A = rotation(0.7, Vec<3>::Unit(axis)) * R * 1.7;
        EXPECT_LT(energy.value(0, Eigen::Map<const Vec<9>>(A.data())), 1e-28);
        const Mat<3> tilted = rotation(0.1, Vec<3>(1, 1, 0) + Vec<3>::Unit(axis)) * A;
        EXPECT_GT(energy.value(0, Eigen::Map<const Vec<9>>(tilted.data())), 1e-4);
        // Residuals in units of a unit edge: scale-free rows.
        const LinearConstraintEnergy<9, 2> small({planarity_rows(axis, 1e-3 * edges)});
        EXPECT_NEAR(small.value(0, Eigen::Map<const Vec<9>>(tilted.data())),
                    energy.value(0, Eigen::Map<const Vec<9>>(tilted.data())), 1e-12);
    }
    EXPECT_THROW(planarity_rows(3, edges), InvalidArgumentError);
    EXPECT_THROW(planarity_rows(0, Eigen::Matrix<double, 3, 2>::Zero()), InvalidArgumentError);
}

TEST(PolycubeConstraints, VertexPlanarityAndSlidingRows) {
    const LinearConstraintEnergy<9, 2> planar({planarity_vertex_rows(2, {2.0, 4.0})});
    Vec<9> x;
    x << 0, 0, 1, 2, 0, 1, 0, 4, 1;
    EXPECT_EQ(planar.value(0, x), 0.0);
    x[8] = 2.0;  // the third vertex one unit higher: residual 1 / 4
    EXPECT_NEAR(planar.value(0, x), 1.0 / 16.0, 1e-15);

    // A rest point u of a tetrahedron with (A, T) sliding along the line x = 1, z = 3.
    const Vec<3> u(0.2, -0.1, 0.3);
    const LinearConstraintEnergy<12, 2> line({sliding_rows<2>(u, {0, 2}, {1.0, 3.0})});
    Mat<3> A = rotation(0.3, Vec<3>(1, 2, 3)) * 1.2;
    Vec<12> at;
    at.head<9>() = Eigen::Map<const Vec<9>>(A.data());
    at.tail<3>() = Vec<3>(1.0, 7.0, 3.0) - A * u;
    EXPECT_LT(line.value(0, at), 1e-28);
    at[10] += 5.0;  // along the line: still on it
    EXPECT_LT(line.value(0, at), 1e-28);
    at[9] += 0.5;  // off it
    EXPECT_NEAR(line.value(0, at), 0.25, 1e-14);
    EXPECT_TRUE(check_derivatives(line, 0, at).passes(1e-7));

    const LinearConstraintEnergy<3, 3> corner({sliding_vertex_rows<3>({0, 1, 2}, {1, 2, 3})});
    EXPECT_EQ(corner.value(0, Vec<3>(1, 2, 3)), 0.0);
    EXPECT_EQ(corner.value(0, Vec<3>(1, 2, 4)), 1.0);
    EXPECT_THROW((sliding_vertex_rows<2>({1, 1}, {0, 0})), InvalidArgumentError);
}

}  // namespace
}  // namespace sa
