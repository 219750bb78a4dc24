// Hex-mesh measures (geometry/quality/hex_quality.h) and point-to-surface distances
// (geometry/quality/surface_distance.h).
#include "geometry/quality/hex_quality.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "geometry/quality/surface_distance.h"
#include "optim/errors.h"

namespace sa {
namespace {

/// `nx` unit cubes in a row along x: 4 (nx + 1) vertices, positively oriented hexes.
HexMesh row_of_cubes(int nx) {
    HexMesh mesh;
    mesh.positions.resize(4 * (nx + 1), 3);
    for (int i = 0; i <= nx; ++i) {
        mesh.positions.row(4 * i + 0) << i, 0, 0;
        mesh.positions.row(4 * i + 1) << i, 1, 0;
        mesh.positions.row(4 * i + 2) << i, 1, 1;
        mesh.positions.row(4 * i + 3) << i, 0, 1;
    }
    mesh.hexes.resize(nx, 8);
    for (int i = 0; i < nx; ++i) {
        const int a = 4 * i, b = 4 * (i + 1);
        // (0,0,0) (1,0,0) (1,1,0) (0,1,0) (0,0,1) (1,0,1) (1,1,1) (0,1,1)
        mesh.hexes.row(i) << a, b, b + 1, a + 1, a + 3, b + 3, b + 2, a + 2;
    }
    return mesh;
}

TEST(HexQuality, ACuboidHasScaledJacobianOneAndItsVolume) {
    HexMesh mesh = row_of_cubes(1);
    mesh.positions.col(2) *= 3.0;  // a 1 x 1 x 3 cuboid
    EXPECT_NEAR(hex_scaled_jacobian(mesh, 0), 1.0, 1e-15);
    EXPECT_NEAR(hex_min_corner_jacobian(mesh, 0), 3.0, 1e-14);
    EXPECT_NEAR(hex_volume(mesh, 0), 3.0, 1e-14);
    const HexQuality q = hex_quality(mesh);
    EXPECT_EQ(q.inverted, 0);
    EXPECT_EQ(q.histogram[10], 1);
    EXPECT_NEAR(q.mean_scaled_jacobian, 1.0, 1e-15);
}

TEST(HexQuality, ACornerPushedThroughTheHexInvertsIt) {
    HexMesh mesh = row_of_cubes(1);
    const int top = mesh.hexes(0, 6);  // (1, 1, 1)
    mesh.positions.row(top) << 0.1, 0.1, 0.1;
    EXPECT_LT(hex_min_corner_jacobian(mesh, 0), 0.0);
    EXPECT_LT(hex_scaled_jacobian(mesh, 0), 0.0);
    const HexQuality q = hex_quality(mesh);
    EXPECT_EQ(q.inverted, 1);
    EXPECT_EQ(q.histogram[0], 1);
    // A shear keeps it valid with a scaled Jacobian below one.
    mesh = row_of_cubes(1);
    for (int c = 4; c < 8; ++c) mesh.positions(mesh.hexes(0, c), 0) += 0.5;
    EXPECT_NEAR(hex_scaled_jacobian(mesh, 0), 1.0 / std::sqrt(1.25), 1e-12);
    EXPECT_EQ(hex_quality(mesh).inverted, 0);
}

TEST(HexQuality, BoundaryOfARowIsClosedAndHexesTouchingAtAnEdgeAreNot) {
    const HexMesh row = row_of_cubes(3);
    const HexBoundary b = hex_boundary(row);
    EXPECT_EQ(b.quads.rows(), 14);  // 4 sides x 3 + 2 ends
    EXPECT_TRUE(b.closed());
    // Every vertex of a row of cubes is on its boundary.
    EXPECT_EQ(std::count(b.on_boundary.begin(), b.on_boundary.end(), 1), row.num_vertices());
    // Faces turn counter-clockwise seen from outside: the boundary encloses a positive volume
    // (divergence theorem on the quads split in two).
    double volume = 0.0;
    for (Eigen::Index q = 0; q < b.quads.rows(); ++q) {
        for (int k : {1, 2}) {
            const Eigen::Vector3d x0 = row.positions.row(b.quads(q, 0));
            const Eigen::Vector3d x1 = row.positions.row(b.quads(q, k));
            const Eigen::Vector3d x2 = row.positions.row(b.quads(q, k + 1));
            volume += x0.dot(x1.cross(x2)) / 6.0;
        }
    }
    EXPECT_NEAR(volume, 3.0, 1e-12);

    // Two cubes that share one edge only: that edge is in four boundary faces.
    HexMesh two = row_of_cubes(1);
    HexMesh other = row_of_cubes(1);
    other.positions.rowwise() += Eigen::RowVector3d(1.0, 1.0, 0.0);
    HexMesh both;
    both.positions.resize(16, 3);
    both.positions << two.positions, other.positions;
    both.hexes.resize(2, 8);
    both.hexes << two.hexes, other.hexes.array() + 8;
    // Merge the shared edge's vertices: (1,1,0) and (1,1,1).
    for (int c = 0; c < 8; ++c) {
        const Eigen::RowVector3d x = both.positions.row(both.hexes(1, c));
        for (int v = 0; v < 8; ++v)
            if ((both.positions.row(v) - x).norm() < 1e-12) both.hexes(1, c) = v;
    }
    const HexBoundary touching = hex_boundary(both);
    EXPECT_FALSE(touching.closed());
    EXPECT_EQ(touching.open_edges, 1);
}

TEST(SurfaceDistance, MatchesTheClosestTriangleByBruteForce) {
    // A bumpy closed surface: an octahedron's faces, subdivided and pushed out.
    Eigen::MatrixXd vertices(6, 3);
    vertices << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1;
    Eigen::MatrixXi triangles(8, 3);
    triangles << 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5;
    vertices.row(4) *= 1.7;
    const SurfaceDistance surface(vertices, triangles);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
    for (int i = 0; i < 200; ++i) {
        const Eigen::Vector3d p(coordinate(random), coordinate(random), coordinate(random));
        double brute = std::numeric_limits<double>::infinity();
        for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
            brute = std::min(brute, point_triangle_distance(p, vertices.row(triangles(f, 0)),
                                                            vertices.row(triangles(f, 1)),
                                                            vertices.row(triangles(f, 2))));
        }
        EXPECT_NEAR(surface.distance(p), brute, 1e-14) << i;
    }
    // Regions: a corner, an edge, the face.
    const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    EXPECT_NEAR(point_triangle_distance({-1, -1, 0}, a, b, c), std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(point_triangle_distance({0.5, -2, 0}, a, b, c), 2.0, 1e-15);
    EXPECT_NEAR(point_triangle_distance({0.2, 0.2, 0.5}, a, b, c), 0.5, 1e-15);
    EXPECT_NEAR(point_triangle_distance({1, 1, 0}, a, b, c), std::sqrt(0.5), 1e-15);
    // A degenerate triangle is its segment.
    EXPECT_NEAR(point_triangle_distance({0.5, 1, 0}, a, b, b), 1.0, 1e-15);
    EXPECT_THROW(SurfaceDistance(vertices, Eigen::MatrixXi(0, 3)), InvalidArgumentError);
}

}  // namespace
}  // namespace sa
