#include "frontends/polycube/polycube_boundary_monotonicity.h"

#include <gtest/gtest.h>

#include "tests/fixtures/polycube_fixtures.h"

namespace sa {
namespace {

using testing::HookedCube;

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
    EXPECT_NEAR(found[0].backward_travel, 4.0 / HookedCube::kResolution, 1e-12);
    EXPECT_NEAR(cube.mesh.vertices(found[0].vertex, 0), 1.0 - 4.0 / HookedCube::kResolution, 1e-12);
}

}  // namespace
}  // namespace sa
