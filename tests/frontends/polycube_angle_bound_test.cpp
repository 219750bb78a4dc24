#include "frontends/polycube/polycube_angle_bound.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>
#include <random>

#include "optim/errors.h"
#include "tests/fixtures/polycube_fixtures.h"

namespace sa {
namespace {

using testing::HookedCube;

double degrees(double d) {
    return d * M_PI / 180.0;
}

TEST(PolycubeAngleBound, OneAngleNeedsTheRatioOfHalfAngleTangents) {
    // One angle alpha opened to beta needs K = tan(beta/2) / tan(alpha/2), closed the inverse.
    EXPECT_NEAR(wedge_distortion_bound({degrees(30)}, degrees(90)),
                std::tan(degrees(45)) / std::tan(degrees(15)), 1e-9);
    EXPECT_NEAR(wedge_distortion_bound({degrees(150)}, degrees(90)),
                std::tan(degrees(75)) / std::tan(degrees(45)), 1e-9);
    // Two equal angles share the opening: each 2 alpha -> beta / 2.
    EXPECT_NEAR(wedge_distortion_bound({degrees(0.37), degrees(0.37)}, M_PI),
                std::tan(degrees(45)) / std::tan(degrees(0.185)), 1e-6);
    EXPECT_EQ(wedge_distortion_bound({degrees(45), degrees(45)}, M_PI / 2), 1.0);
    // One triangle cannot open to pi: it would be flat.
    EXPECT_EQ(wedge_distortion_bound({degrees(60)}, M_PI), kInfinity);
    EXPECT_THROW(wedge_distortion_bound({}, M_PI), InvalidArgumentError);
}

TEST(PolycubeAngleBound, ALinearMapKeepsAnglesWithinTheRangeOfItsRatio) {
    // The inequality the bound rests on, for random maps and planar angles: 2 atan(tan(a/2)/K)
    // <= beta <= 2 atan(K tan(a/2)), K = sigma_max / sigma_min of the 3 x 3 map.
    std::mt19937 rng(7);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> uniform(0.01, M_PI - 0.01);
    for (int trial = 0; trial < 2000; ++trial) {
        Eigen::Matrix3d a;
        for (int i = 0; i < 9; ++i) a(i / 3, i % 3) = normal(rng);
        const Eigen::Vector3d s = Eigen::JacobiSVD<Eigen::Matrix3d>(a).singularValues();
        const double k = s[0] / s[2];
        const Eigen::Vector3d u = Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
        Eigen::Vector3d w = Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
        const Eigen::Vector3d e1 = u.normalized();
        const Eigen::Vector3d e2 = (w - w.dot(e1) * e1).normalized();
        const double alpha = uniform(rng);
        const Eigen::Vector3d x = e1, y = std::cos(alpha) * e1 + std::sin(alpha) * e2;
        const Eigen::Vector3d ax = a * x, ay = a * y;
        const double beta = std::atan2(ax.cross(ay).norm(), ax.dot(ay));
        const double t = std::tan(0.5 * alpha);
        EXPECT_LE(beta, 2.0 * std::atan(k * t) + 1e-9);
        EXPECT_GE(beta, 2.0 * std::atan(t / k) - 1e-9);
    }
}

TEST(PolycubeAngleBound, ACubeForcesNothing) {
    const HookedCube cube;
    const PolycubeCharts charts = polycube_charts(cube.boundary, cube.mesh.vertices, cube.labels);
    const PolycubeAngleBound b = polycube_angle_bound(cube.boundary, charts, cube.mesh.vertices);
    EXPECT_NEAR(b.bound, 1.0, 1e-9);
    ASSERT_EQ(b.worst.size(), 5u);
}

TEST(PolycubeAngleBound, AHooksCornersForceDistortion) {
    // The hook's +X triangles on the +Y face: at its corners the +X chart's wedges are 45 or 90
    // degrees (Kuhn triangles) where the PolyCube has 90, 180 or 270.
    HookedCube cube;
    cube.add_hook();
    const PolycubeCharts charts = polycube_charts(cube.boundary, cube.mesh.vertices, cube.labels);
    const PolycubeAngleBound b = polycube_angle_bound(cube.boundary, charts, cube.mesh.vertices);
    ASSERT_FALSE(b.worst.empty());
    const WedgeAngleBound& w = b.worst.front();
    EXPECT_EQ(b.bound, w.bound);
    EXPECT_GT(w.bound, 1.5);
    // A wedge of one 45-degree triangle opened to 90 degrees is the least any hook corner needs.
    EXPECT_GE(w.bound, std::tan(degrees(45)) / std::tan(degrees(22.5)) - 1e-9);
    // It is at a vertex of the hook: on the +Y face (y = 1), away from the cube's edges.
    EXPECT_NEAR(cube.mesh.vertices(w.vertex, 1), 1.0, 1e-12);
    for (std::size_t i = 1; i < b.worst.size(); ++i)
        EXPECT_GE(b.worst[i - 1].bound, b.worst[i].bound);
}

TEST(PolycubeAngleBound, ATriangleThatMustBeFlatHasNoValidMap) {
    // One +Y triangle with an edge on the cube's +X | +Y edge relabelled +X: its third vertex
    // is on the +X | +Y boundary only, where the one triangle must open to 180 degrees.
    HookedCube cube;
    for (Index b = 0; b < cube.boundary.size(); ++b) {
        if (cube.labels[b] != 2) continue;
        int on_edge = 0, middle = 0;  // away from the cube's corners
        for (int k = 0; k < 3; ++k) {
            const auto p = cube.mesh.vertices.row(cube.boundary.triangles(b, k));
            on_edge += p.x() == 1.0;
            middle += p.z() > 0.3 && p.z() < 0.7;
        }
        if (on_edge == 2 && middle == 3) {
            cube.labels[b] = 0;
            break;
        }
    }
    const PolycubeCharts charts = polycube_charts(cube.boundary, cube.mesh.vertices, cube.labels);
    const PolycubeAngleBound b = polycube_angle_bound(cube.boundary, charts, cube.mesh.vertices);
    EXPECT_EQ(b.bound, kInfinity);
    ASSERT_FALSE(b.worst.empty());
    EXPECT_EQ(b.worst.front().label, 0);
    EXPECT_EQ(b.worst.front().wedges, 2);
    EXPECT_EQ(b.worst.front().triangles, 1);
    EXPECT_NEAR(b.worst.front().image_angle, M_PI, 1e-15);
}

TEST(PolycubeAngleBound, APinchedVertexIsLeftOut) {
    // Two tetrahedra sharing vertex 0 only, each boundary one chart: at vertex 0 each wedge is
    // a whole fan of its own surface, not half of one PolyCube edge.
    SimplicialMesh mesh;
    mesh.vertices.resize(7, 3);
    mesh.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1;
    mesh.simplices.resize(2, 4);
    mesh.simplices << 0, 1, 2, 3, 0, 5, 4, 6;
    const TetBoundary boundary = tet_boundary(mesh, mesh_topology(mesh, "pinch"));
    std::vector<int> labels(boundary.size(), 0);
    for (Index b = 0; b < boundary.size(); ++b) labels[b] = boundary.tet(b) == 0 ? 0 : 1;
    const PolycubeCharts charts = polycube_charts(boundary, mesh.vertices, labels);
    ASSERT_EQ(charts.size(), 2);
    const PolycubeAngleBound b = polycube_angle_bound(boundary, charts, mesh.vertices, 10);
    EXPECT_EQ(b.worst.size(), 6u);
    for (const WedgeAngleBound& w : b.worst) EXPECT_NE(w.vertex, 0);
}

}  // namespace
}  // namespace sa
