#include "frontends/polycube/polycube_label_cleanup.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "tests/fixtures/polycube_fixtures.h"

namespace sa {
namespace {

using testing::bent;
using testing::l_shape;
using testing::voxel_tetrahedra;

// Random labels on isolated boundary triangles inside the faces of a generated shape (no two
// noisy triangles within two steps, none beside another face): each becomes a chart of one
// triangle, too small, and must go back to its face.
TEST(PolycubeLabelCleanup, NoisyLabellingReturnsToTheFaces) {
    for (const unsigned seed : {1u, 2u, 3u}) {
        const SimplicialMesh mesh = bent(voxel_tetrahedra(l_shape(), 4), 0.02);
        const MeshTopology topology = mesh_topology(mesh, "L");
        const TetBoundary boundary = tet_boundary(mesh, topology);
        const std::vector<int> truth = closest_axis_labels(boundary, mesh.vertices);
        ASSERT_EQ(polycube_charts(boundary, mesh.vertices, truth).size(), 8);
        std::vector<int> labels = truth;
        std::mt19937 random(seed);
        std::set<Index> noisy;
        for (int tries = 0; tries < 4000 && noisy.size() < 30; ++tries) {
            const Index b = Index(random() % boundary.size());
            bool isolated = !noisy.count(b);
            for (const Index n : boundary.adjacent[b]) {
                isolated = isolated && !noisy.count(n) && truth[n] == truth[b];
                // Nor beside a noisy triangle or another face through a neighbour, which could
                // cut a triangle off its face.
                for (const Index m : boundary.adjacent[n]) {
                    isolated = isolated && truth[m] == truth[b] && (m == b || !noisy.count(m));
                }
            }
            if (!isolated) continue;
            labels[b] = (truth[b] + 1 + int(random() % 5)) % 6;
            noisy.insert(b);
        }
        ASSERT_EQ(noisy.size(), 30u);
        const LabelCleanupReport report = clean_polycube_labels(boundary, mesh.vertices, labels);
        EXPECT_TRUE(report.clean);
        EXPECT_EQ(labels, truth) << "seed " << seed;
        EXPECT_EQ(report.triangles_changed, 30);
        EXPECT_EQ(report.charts_after, 8);
        EXPECT_EQ(report.charts_before, 8 + 30);
        EXPECT_EQ(report.merged_small, report.charts_before - 8);
        EXPECT_NO_THROW(validate_polycube_labels(mesh, boundary, labels, "L"));
    }
}

// A patch of nine triangles labelled -Z in the middle of the +Y face of a box: large enough,
// but with one neighbour only. It goes back to +Y.
TEST(PolycubeLabelCleanup, AChartWithFewNeighboursIsMerged) {
    const SimplicialMesh mesh = voxel_tetrahedra({{0, 0, 0}}, 6);
    const TetBoundary boundary = tet_boundary(mesh, mesh_topology(mesh, "box"));
    const std::vector<int> truth = closest_axis_labels(boundary, mesh.vertices);
    std::vector<int> labels = truth;
    Index changed = 0;
    for (Index b = 0; b < boundary.size(); ++b) {
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();
        for (int i = 0; i < 3; ++i) centre += mesh.vertices.row(boundary.triangles(b, i));
        centre /= 3.0;
        if (truth[b] == 2 && std::abs(centre.x() - 0.5) < 0.17 &&
            std::abs(centre.z() - 0.5) < 0.17) {
            labels[b] = 5;
            ++changed;
        }
    }
    ASSERT_GE(changed, 8);
    LabelCleanupOptions options;
    options.min_triangles = 3;
    options.min_area_fraction = 0.0;
    const LabelCleanupReport report =
        clean_polycube_labels(boundary, mesh.vertices, labels, options);
    EXPECT_EQ(report.merged_few_neighbours, 1);
    EXPECT_EQ(report.merged_small, 0);
    EXPECT_EQ(labels, truth);
    EXPECT_EQ(report.triangles_changed, changed);
}

// The two roof faces of a steep prism, -X and +X, meet at the ridge: the smaller goes.
TEST(PolycubeLabelCleanup, OppositeChartsAreSeparated) {
    SimplicialMesh mesh;
    mesh.vertices.resize(6, 3);
    // Asymmetric roof: the right face (x from 2 to 1.2) is the smaller one.
    mesh.vertices << 0, 0, 0, 2, 0, 0, 1.2, 3, 0, 0, 0, 1, 2, 0, 1, 1.2, 3, 1;
    mesh.simplices.resize(3, 4);
    mesh.simplices << 0, 1, 2, 3, 1, 2, 3, 4, 2, 3, 4, 5;
    for (Index t = 0; t < 3; ++t) {
        if (tet_orientation(mesh, t) < 0) mesh.simplices.row(t).segment<2>(1).reverseInPlace();
    }
    const TetBoundary boundary = tet_boundary(mesh, mesh_topology(mesh, "roof"));
    std::vector<int> labels = closest_axis_labels(boundary, mesh.vertices);
    LabelCleanupOptions options;
    options.min_triangles = 0;
    options.min_area_fraction = 0.0;
    options.min_neighbours = 0;
    const LabelCleanupReport report =
        clean_polycube_labels(boundary, mesh.vertices, labels, options);
    EXPECT_EQ(report.merged_opposite, 1);
    EXPECT_EQ(report.triangles_changed, 2);
    const PolycubeCharts charts = polycube_charts(boundary, mesh.vertices, labels);
    for (int c = 0; c < charts.size(); ++c) {
        for (const int n : charts.neighbours[c]) EXPECT_NE(charts.label[n], charts.label[c] ^ 1);
        EXPECT_NE(charts.label[c], 0);  // +X was the smaller face
    }
}

TEST(PolycubeLabelCleanup, ACleanLabellingIsLeftAlone) {
    const SimplicialMesh mesh = bent(voxel_tetrahedra(l_shape(), 3), 0.02);
    const TetBoundary boundary = tet_boundary(mesh, mesh_topology(mesh, "L"));
    const std::vector<int> truth = closest_axis_labels(boundary, mesh.vertices);
    std::vector<int> labels = truth;
    const LabelCleanupReport report = clean_polycube_labels(boundary, mesh.vertices, labels);
    EXPECT_TRUE(report.clean);
    EXPECT_EQ(report.rounds, 0);
    EXPECT_EQ(report.triangles_changed, 0);
    EXPECT_EQ(labels, truth);
}

// Teeth along a PolyCube edge: on a box, the +X triangles with an edge on the vertical edge x = y =
// 1 are labelled +Y in every other cell, so that the boundary between the two charts zigzags off
// the edge. No chart is small or short of neighbours; the teeth rule takes the triangles back to
// +X.
TEST(PolycubeLabelCleanup, TeethAlongAnEdgeAreRemoved) {
    const SimplicialMesh mesh = voxel_tetrahedra({{0, 0, 0}}, 6);
    const TetBoundary boundary = tet_boundary(mesh, mesh_topology(mesh, "box"));
    const std::vector<int> truth = closest_axis_labels(boundary, mesh.vertices);
    std::vector<int> labels = truth;
    int teeth = 0;
    for (Index b = 0; b < boundary.size(); ++b) {
        int on_edge = 0;
        double z = 0.0;
        for (int i = 0; i < 3; ++i) {
            const Eigen::RowVector3d p = mesh.vertices.row(boundary.triangles(b, i));
            on_edge += p.x() == 1.0 && p.y() == 1.0;
            z += p.z() / 3.0;
        }
        if (labels[b] == 0 && on_edge == 2 && int(std::floor(6.0 * z)) % 2 == 1) {
            labels[b] = 2;
            ++teeth;
        }
    }
    ASSERT_GT(teeth, 2);
    const std::vector<int> toothed = labels;
    LabelCleanupOptions off;
    off.remove_teeth = false;
    const LabelCleanupReport kept = clean_polycube_labels(boundary, mesh.vertices, labels, off);
    EXPECT_TRUE(kept.clean);
    EXPECT_EQ(labels, toothed);
    const LabelCleanupReport report = clean_polycube_labels(boundary, mesh.vertices, labels);
    EXPECT_TRUE(report.clean);
    EXPECT_EQ(labels, truth);
    EXPECT_EQ(report.triangles_changed, teeth);
    EXPECT_GE(report.teeth, teeth);
    EXPECT_EQ(report.charts_after, 6);
}

}  // namespace
}  // namespace sa
