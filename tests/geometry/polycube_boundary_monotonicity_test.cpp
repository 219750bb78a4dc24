#include "geometry/polycube_boundary_monotonicity.h"

#include <gtest/gtest.h>

#include "polycube_fixtures.h"

namespace sa {
namespace {

using testing::voxel_tetrahedra;

constexpr int kResolution = 12;

// The unit cube cut into 12^3 voxels, labelled by closest axis, with a hook of +X on its +Y face
// (y = 1): a bar of 6 x 2 voxels from the +X|+Y edge at z in [0.5, 0.5 + 2/12], and at its far
// end a leg of 2 voxels hanging down 4 voxels below the bar. The +X|+Y boundary runs up the
// cube's edge, around the bar and the leg and back: down the leg's inner side, against the
// direction (+Z) of the rest of it.
struct HookedCube {
    SimplicialMesh mesh = voxel_tetrahedra({{0, 0, 0}}, kResolution);
    TetBoundary boundary = tet_boundary(mesh, mesh_topology(mesh, "cube"));
    std::vector<int> labels = closest_axis_labels(boundary, mesh.vertices);

    void add_hook() {
        const double h = 1.0 / kResolution;
        for (Index b = 0; b < boundary.size(); ++b) {
            Eigen::Vector3d c = Eigen::Vector3d::Zero();
            for (int i = 0; i < 3; ++i) c += mesh.vertices.row(boundary.triangles(b, i));
            c /= 3.0;
            if (labels[b] != 2) continue;  // +Y
            const bool bar = c.x() > 1.0 - 6 * h && c.z() > 0.5 && c.z() < 0.5 + 2 * h;
            const bool leg = c.x() > 1.0 - 6 * h && c.x() < 1.0 - 4 * h && c.z() > 0.5 - 4 * h &&
                             c.z() < 0.5 + 2 * h;
            if (bar || leg) labels[b] = 0;  // +X
        }
    }
};

TEST(PolycubeBoundaryMonotonicity, ACubesBoundariesAreMonotone) {
    const HookedCube cube;
    const PolycubeCharts charts = polycube_charts(cube.boundary, cube.mesh.vertices, cube.labels);
    ASSERT_EQ(charts.size(), 6);
    EXPECT_TRUE(
        non_monotone_boundaries(cube.boundary, cube.mesh.vertices, cube.labels, charts).empty());
}

TEST(PolycubeBoundaryMonotonicity, AHookTurnsBack) {
    HookedCube cube;
    cube.add_hook();
    const PolycubeCharts charts = polycube_charts(cube.boundary, cube.mesh.vertices, cube.labels);
    ASSERT_EQ(charts.size(), 6);
    const std::vector<NonMonotoneBoundary> found =
        non_monotone_boundaries(cube.boundary, cube.mesh.vertices, cube.labels, charts);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(charts.label[found[0].chart_a], found[0].label_a);
    EXPECT_EQ(charts.label[found[0].chart_b], found[0].label_b);
    EXPECT_EQ(found[0].label_a + found[0].label_b, 0 + 2);  // +X and +Y
    EXPECT_EQ(found[0].strongly_backward, 4);               // the leg's inner side below the bar
    EXPECT_NEAR(found[0].backward_travel, 4.0 / kResolution, 1e-12);
    EXPECT_NEAR(cube.mesh.vertices(found[0].vertex, 0), 1.0 - 4.0 / kResolution, 1e-12);
}

}  // namespace
}  // namespace sa
