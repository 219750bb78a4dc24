#include "frontends/polycube/polycube_label_repair.h"

#include <gtest/gtest.h>

#include "frontends/polycube/polycube_boundary_monotonicity.h"
#include "tests/fixtures/polycube_fixtures.h"

namespace sa {
namespace {

using testing::HookedCube;

std::vector<NonMonotoneBoundary> turning(const HookedCube& cube) {
    return non_monotone_boundaries(cube.boundary, cube.mesh.vertices, cube.labels,
                                   polycube_charts(cube.boundary, cube.mesh.vertices, cube.labels));
}

TEST(PolycubeLabelRepair, MonotoneLabelsAreLeftAlone) {
    HookedCube cube;
    const std::vector<int> before = cube.labels;
    const LabelRepairReport report =
        repair_turning_boundaries(cube.boundary, cube.mesh.vertices, cube.labels);
    EXPECT_EQ(report.turning_before, 0);
    EXPECT_EQ(report.moves, 0);
    EXPECT_EQ(report.trials, 0);
    EXPECT_EQ(cube.labels, before);
}

TEST(PolycubeLabelRepair, AHookIsRelabelledUntilItsBoundaryIsMonotone) {
    HookedCube cube;
    cube.add_hook();
    ASSERT_EQ(turning(cube).size(), 1u);
    const std::vector<int> before = cube.labels;
    const LabelRepairReport report =
        repair_turning_boundaries(cube.boundary, cube.mesh.vertices, cube.labels);
    EXPECT_EQ(report.turning_before, 1);
    EXPECT_EQ(report.backward_before, 4);
    EXPECT_EQ(report.turning_after, 0);
    EXPECT_EQ(report.backward_after, 0);
    EXPECT_TRUE(turning(cube).empty());
    EXPECT_GE(report.moves, 1);
    // Only patches beside the hook change: the hook has 12 + 8 voxel faces, 40 triangles,
    // the +Y face 288.
    Index changed = 0;
    for (std::size_t b = 0; b < before.size(); ++b) changed += before[b] != cube.labels[b];
    EXPECT_EQ(changed, report.triangles_changed);
    EXPECT_GT(changed, 0);
    EXPECT_LE(changed, 60);
    // Still a usable labelling: every chart faces its side, no opposite labels adjacent.
    EXPECT_NO_THROW(validate_polycube_labels(cube.mesh, cube.boundary, cube.labels, "cube"));
}

}  // namespace
}  // namespace sa
