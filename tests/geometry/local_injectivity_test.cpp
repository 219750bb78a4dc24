#include "geometry/quality/local_injectivity.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/mesh/rest_frames.h"
#include "geometry/quality/map_quality.h"

namespace sa {
namespace {

constexpr int kRing = 8;

// A fan of kRing triangles around vertex 0 (a regular polygon), inside a second ring so that the
// first ring's vertices are interior too.
SimplicialMesh two_ring_fan() {
    SimplicialMesh mesh;
    mesh.vertices.resize(1 + 2 * kRing, 2);
    mesh.vertices.row(0) << 0.0, 0.0;
    for (int k = 0; k < kRing; ++k) {
        const double a = 2.0 * M_PI * k / kRing, b = a + M_PI / kRing;
        mesh.vertices.row(1 + k) << std::cos(a), std::sin(a);
        mesh.vertices.row(1 + kRing + k) << 2.0 * std::cos(b), 2.0 * std::sin(b);
    }
    mesh.simplices.resize(3 * kRing, 3);
    for (int k = 0; k < kRing; ++k) {
        const int i = 1 + k, j = 1 + (k + 1) % kRing, o = 1 + kRing + k;
        mesh.simplices.row(3 * k) << 0, i, j;
        mesh.simplices.row(3 * k + 1) << i, o, j;
        mesh.simplices.row(3 * k + 2) << j, o, 1 + kRing + (k + 1) % kRing;
    }
    return mesh;
}

// The fan's map that turns `wraps` times around vertex 0: every angle times `wraps`.
Eigen::MatrixXd wrapped(const SimplicialMesh& mesh, int wraps) {
    Eigen::MatrixXd x(mesh.num_vertices(), 2);
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        const double r = mesh.vertices.row(v).norm(),
                     a = std::atan2(mesh.vertices(v, 1), mesh.vertices(v, 0));
        x.row(v) << r * std::cos(wraps * a), r * std::sin(wraps * a);
    }
    return x;
}

TEST(LocalInjectivity, ABranchPointWithEveryTrianglePositiveIsFound) {
    const SimplicialMesh mesh = two_ring_fan();
    const MeshTopology topology = mesh_topology(mesh, "fan");
    const RestFrames<2> frames = rest_frames<2>(mesh);
    EXPECT_TRUE(branched_vertices(mesh, topology, wrapped(mesh, 1)).empty());
    const Eigen::MatrixXd twice = wrapped(mesh, 2);
    EXPECT_EQ(map_quality<2>(linear_parts<2>(mesh, frames, twice), frames.volume).inverted, 0);
    EXPECT_EQ(branched_vertices(mesh, topology, twice), std::vector<Index>{0});
    // Listed clockwise, the same maps mirrored: the same answers.
    SimplicialMesh mirrored = mesh;
    mirrored.simplices.col(1).swap(mirrored.simplices.col(2));
    const MeshTopology mirrored_topology = mesh_topology(mirrored, "mirrored fan");
    EXPECT_TRUE(branched_vertices(mirrored, mirrored_topology, wrapped(mirrored, 1)).empty());
    EXPECT_EQ(branched_vertices(mirrored, mirrored_topology, wrapped(mirrored, 2)),
              std::vector<Index>{0});
}

// kRing tetrahedra around the edge from (0, 0, -1) to (0, 0, 1), closed by a ring of points.
SimplicialMesh edge_star() {
    SimplicialMesh mesh;
    mesh.vertices.resize(2 + kRing, 3);
    mesh.vertices.row(0) << 0, 0, -1;
    mesh.vertices.row(1) << 0, 0, 1;
    for (int k = 0; k < kRing; ++k) {
        const double a = 2.0 * M_PI * k / kRing;
        mesh.vertices.row(2 + k) << std::cos(a), std::sin(a), 0.0;
    }
    mesh.simplices.resize(kRing, 4);
    for (int k = 0; k < kRing; ++k) mesh.simplices.row(k) << 0, 1, 2 + k, 2 + (k + 1) % kRing;
    return mesh;
}

// The edge star's map that turns `wraps` times around the edge.
Eigen::MatrixXd wrapped_star(const SimplicialMesh& mesh, int wraps) {
    Eigen::MatrixXd x = mesh.vertices;
    for (int k = 0; k < kRing; ++k) {
        const double a = 2.0 * M_PI * wraps * k / kRing;
        x.row(2 + k) << std::cos(a), std::sin(a), 0.0;
    }
    return x;
}

TEST(LocalInjectivity, ATetrahedralMapWrappedTwiceAroundAnEdgeIsFound) {
    const SimplicialMesh mesh = edge_star();
    const MeshTopology topology = mesh_topology(mesh, "edge star");
    const RestFrames<3> frames = rest_frames<3>(mesh);
    for (int wraps : {1, 2}) {
        const Eigen::MatrixXd x = wrapped_star(mesh, wraps);
        const MapQuality q = map_quality<3>(linear_parts<3>(mesh, frames, x), frames.volume);
        EXPECT_EQ(q.inverted, 0);
        const std::vector<Index> branched = branched_edges(mesh, topology, x);
        if (wraps == 1) {
            EXPECT_TRUE(branched.empty());
        } else {
            ASSERT_EQ(branched.size(), 1u);
            EXPECT_EQ(topology.edges[branched[0]], (std::array<Index, 2>{0, 1}));
        }
    }
}

TEST(LocalInjectivity, WrappedSimplicesAreTheStarsOfTheWrapsFromTheLinearParts) {
    {
        const SimplicialMesh mesh = edge_star();
        const MeshTopology topology = mesh_topology(mesh, "edge star");
        const RestFrames<3> frames = rest_frames<3>(mesh);
        auto wrapped_of = [&](const Eigen::MatrixXd& x) {
            return wrapped_simplices<3>(mesh, topology, frames, linear_parts<3>(mesh, frames, x));
        };
        EXPECT_TRUE(wrapped_of(wrapped_star(mesh, 1)).empty());
        std::vector<Index> star(kRing);
        for (int k = 0; k < kRing; ++k) star[k] = k;
        EXPECT_EQ(wrapped_of(wrapped_star(mesh, 2)), star);
        // One tetrahedron turned inside out: the star is not all positive, so not looked at
        // (its inverted tetrahedron is what keeps the map from being valid).
        Eigen::MatrixXd folded = wrapped_star(mesh, 2);
        folded.row(2).swap(folded.row(3));
        EXPECT_GT(map_quality<3>(linear_parts<3>(mesh, frames, folded), frames.volume).inverted, 0);
        EXPECT_TRUE(wrapped_of(folded).empty());
    }
    {
        const SimplicialMesh mesh = two_ring_fan();
        const MeshTopology topology = mesh_topology(mesh, "fan");
        const RestFrames<2> frames = rest_frames<2>(mesh);
        auto wrapped_of = [&](const Eigen::MatrixXd& x) {
            return wrapped_simplices<2>(mesh, topology, frames, linear_parts<2>(mesh, frames, x));
        };
        EXPECT_TRUE(wrapped_of(wrapped(mesh, 1)).empty());
        // Twice around vertex 0: its star, the triangles 3k (the first ring's vertices turn once).
        std::vector<Index> star;
        for (int k = 0; k < kRing; ++k) star.push_back(3 * k);
        EXPECT_EQ(wrapped_of(wrapped(mesh, 2)), star);
    }
}

}  // namespace
}  // namespace sa
