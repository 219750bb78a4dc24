#include "frontends/seamless/cross_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/mesh/mesh_generators.h"
#include "optim/errors.h"

namespace sa {
namespace {

double index_sum(const std::vector<Singularity>& singularities) {
    double sum = 0.0;
    for (const Singularity& s : singularities) {
        EXPECT_EQ(4.0 * s.index, std::round(4.0 * s.index)) << "vertex " << s.vertex;
        sum += s.index;
    }
    return sum;
}

// A random tangent direction per face.
Eigen::MatrixXd random_field(const SimplicialMesh& mesh, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> normal;
    Eigen::MatrixXd d(mesh.num_simplices(), 3);
    for (Index f = 0; f < mesh.num_simplices(); ++f) {
        const Eigen::Vector3d p0 = mesh.vertices.row(mesh.simplices(f, 0)).transpose();
        const Eigen::Vector3d a = mesh.vertices.row(mesh.simplices(f, 1)).transpose() - p0;
        const Eigen::Vector3d b = mesh.vertices.row(mesh.simplices(f, 2)).transpose() - p0;
        d.row(f) = (normal(rng) * a + normal(rng) * b).normalized().transpose();
    }
    return d;
}

TEST(CrossField, IndicesSumToTheEulerCharacteristic) {
    const SimplicialMesh sphere = sphere_triangles(6), torus = torus_triangles(24, 12);
    for (const auto& [mesh, chi] : {std::pair{sphere, 2.0}, std::pair{torus, 0.0}}) {
        const MeshTopology t = mesh_topology(mesh, "closed");
        const Eigen::MatrixXd smooth = smoothest_cross_field(mesh, t);
        EXPECT_DOUBLE_EQ(index_sum(cross_field_singularities(mesh, t, smooth)), chi);
        EXPECT_DOUBLE_EQ(index_sum(cross_field_singularities(mesh, t, random_field(mesh, 5))), chi);
    }
}

TEST(CrossField, SmoothestFieldIsSmootherThanARandomOne) {
    const SimplicialMesh sphere = sphere_triangles(6);
    const MeshTopology t = mesh_topology(sphere, "sphere");
    const auto smooth = cross_field_singularities(sphere, t, smoothest_cross_field(sphere, t));
    const auto noisy = cross_field_singularities(sphere, t, random_field(sphere, 5));
    // A cross field on the sphere needs 8 singularities of index 1/4 at least.
    EXPECT_GE(smooth.size(), 8u);
    EXPECT_LE(smooth.size(), 12u);
    EXPECT_GT(noisy.size(), 3 * smooth.size());
}

TEST(CrossField, BoundaryAlignedFieldOnASquareIsConstant) {
    const SimplicialMesh square = grid_triangles(10, 10);
    const MeshTopology t = mesh_topology(square, "square");
    const Eigen::MatrixXd d = smoothest_cross_field(square, t);
    for (Index f = 0; f < square.num_simplices(); ++f) {
        const double angle = std::atan2(d(f, 1), d(f, 0));
        EXPECT_NEAR(std::sin(4.0 * angle), 0.0, 1e-9) << "face " << f;  // along x or y
        EXPECT_NEAR(d(f, 2), 0.0, 1e-12);
    }
    EXPECT_TRUE(cross_field_singularities(square, t, d).empty());
}

TEST(CrossField, IndexOfAFieldTurningAroundAVertex) {
    // On a flat square, the field turning by a quarter of the polar angle around the middle vertex
    // (0.5, 0.5) has index +1/4 there, and -1/4 when it turns the other way; no other singularity.
    const SimplicialMesh square = grid_triangles(10, 10);
    const MeshTopology t = mesh_topology(square, "square");
    const Index middle = 5 * 11 + 5;
    for (double turn : {0.25, -0.25}) {
        Eigen::MatrixXd d = Eigen::MatrixXd::Zero(square.num_simplices(), 3);
        for (Index f = 0; f < square.num_simplices(); ++f) {
            Eigen::RowVector2d c = Eigen::RowVector2d::Zero();
            for (int k = 0; k < 3; ++k) c += square.vertices.row(square.simplices(f, k)) / 3.0;
            const double angle = turn * std::atan2(c.y() - 0.5, c.x() - 0.5);
            d.row(f) << std::cos(angle), std::sin(angle), 0.0;
        }
        const auto s = cross_field_singularities(square, t, d);
        ASSERT_EQ(s.size(), 1u);
        EXPECT_EQ(s[0].vertex, middle);
        EXPECT_DOUBLE_EQ(s[0].index, turn);
    }
}

TEST(CrossField, RejectsAFieldOfTheWrongShapeOrNotTangent) {
    const SimplicialMesh square = grid_triangles(2, 2);
    const MeshTopology t = mesh_topology(square, "square");
    EXPECT_THROW(cross_field_singularities(square, t, Eigen::MatrixXd::Ones(7, 3)), InputError);
    Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(8, 3);
    normal.col(2).setOnes();
    EXPECT_THROW(cross_field_singularities(square, t, normal), InputError);
}

}  // namespace
}  // namespace sa
