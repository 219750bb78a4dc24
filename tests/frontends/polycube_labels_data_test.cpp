// The PolyCube pieces on ../shared/data/polycube (SA_DATA_DIR): label reading and transfer, and
// the squashed-element counts of issue 21, the repair of cup's turning boundaries. Skips when the
// folder is absent.

#include <gtest/gtest.h>

#include <filesystem>

#include "frontends/polycube/polycube_boundary_monotonicity.h"
#include "frontends/polycube/polycube_label_cleanup.h"
#include "frontends/polycube/polycube_label_repair.h"
#include "frontends/polycube/polycube_label_transfer.h"
#include "frontends/polycube/polycube_splits.h"
#include "geometry/io/mesh_file.h"
#include "geometry/io/polycube_labels_io.h"

namespace sa {
namespace {

class PolycubeData : public ::testing::Test {
  protected:
    void SetUp() override {
        if (!std::filesystem::is_directory(root_ + "/polycube")) {
            GTEST_SKIP() << "no shared data at " << root_;
        }
    }
    std::string path(const std::string& relative) const { return root_ + "/polycube/" + relative; }
    std::string root_ = SA_DATA_DIR;
};

TEST_F(PolycubeData, S1FlagsFollowTheOppositeOfTheirReadme) {
    const SimplicialMesh mesh = read_mesh_file(path("polycube_withHexEx/S1.mesh")).mesh;
    const TetBoundary boundary = tet_boundary(mesh, mesh_topology(mesh, "S1.mesh"));
    const std::vector<int> flags =
        read_facet_flags(path("polycube_withHexEx/S1.flags"), mesh.num_simplices());
    LabelConvention convention;
    const std::vector<int> labels = labels_from_file_axes(
        mesh, boundary, boundary_labels_from_flags(boundary, mesh.num_simplices(), flags, "S1"),
        "S1", &convention);
    EXPECT_EQ(convention.outward, 0);
    EXPECT_EQ(convention.inward, boundary.size());
    EXPECT_EQ(convention.negative_tets, 0);
    EXPECT_EQ(polycube_charts(boundary, mesh.vertices, labels).size(), 24);
    EXPECT_NO_THROW(validate_polycube_labels(mesh, boundary, labels, "S1"));
    // Written back in the file's own convention, the flags are the file's.
    EXPECT_EQ(facet_flags(boundary, mesh.num_simplices(), labels, FlagSign::kInward), flags);

    const SquashedElements squashed =
        count_squashed_elements(mesh, facet_flags(boundary, mesh.num_simplices(), labels));
    EXPECT_EQ(squashed.tets, 24);
    EXPECT_EQ(squashed.interior_edges, 18);
}

TEST_F(PolycubeData, FastbndLabelsTransferToExactlyS1Flags) {
    const SimplicialMesh mesh = read_mesh_file(path("polycube_withHexEx/S1.mesh")).mesh;
    const TetBoundary boundary = tet_boundary(mesh, mesh_topology(mesh, "S1.mesh"));
    const SimplicialMesh surface = read_mesh_file(path("fastbndpolycube/boundary.obj")).mesh;
    const std::vector<int> surface_labels =
        read_triangle_labels(path("fastbndpolycube/labeling.txt"), surface.num_simplices());
    const std::vector<int> transferred =
        transfer_surface_labels(mesh, boundary, surface, surface_labels, "boundary.obj");
    const std::vector<int> flags =
        read_facet_flags(path("polycube_withHexEx/S1.flags"), mesh.num_simplices());
    EXPECT_EQ(facet_flags(boundary, mesh.num_simplices(), transferred), flags);
}

TEST_F(PolycubeData, ComputedLabelsOfTheRobustPolycubeMeshesAreCleanAndSplit) {
    for (const char* name : {"B0", "NY_2", "pente", "cup"}) {
        SimplicialMesh mesh =
            read_mesh_file(path(std::string("robustPolycube/") + name + ".mesh")).mesh;
        const TetBoundary boundary = tet_boundary(mesh, mesh_topology(mesh, name));
        std::vector<int> labels = closest_axis_labels(boundary, mesh.vertices);
        const LabelCleanupReport cleanup = clean_polycube_labels(boundary, mesh.vertices, labels);
        EXPECT_TRUE(cleanup.clean) << name;
        EXPECT_NO_THROW(validate_polycube_labels(mesh, boundary, labels, name));
        std::vector<int> flags = facet_flags(boundary, mesh.num_simplices(), labels);
        const PolycubeSplitReport split = split_squashed_elements(mesh, flags, name);
        EXPECT_EQ(split.after.total(), 0) << name;
        if (std::string(name) == "B0") {
            EXPECT_EQ(split.before.total(), 0);
        }
        if (std::string(name) == "cup") {
            EXPECT_GT(split.before.tets, 90);
        }
    }
}

TEST_F(PolycubeData, CupsComputedLabelsNoLongerTurnBackAfterTheRepair) {
    const SimplicialMesh mesh = read_mesh_file(path("robustPolycube/cup.mesh")).mesh;
    const TetBoundary boundary = tet_boundary(mesh, mesh_topology(mesh, "cup"));
    std::vector<int> labels = closest_axis_labels(boundary, mesh.vertices);
    ASSERT_TRUE(clean_polycube_labels(boundary, mesh.vertices, labels).clean);
    const LabelRepairReport report = repair_turning_boundaries(boundary, mesh.vertices, labels);
    EXPECT_EQ(report.turning_before, 3);  // docs/measurements.md, PolyCube
    EXPECT_EQ(report.turning_after, 0);
    EXPECT_LE(report.triangles_changed, 50);
    EXPECT_NO_THROW(validate_polycube_labels(mesh, boundary, labels, "cup"));
    EXPECT_TRUE(non_monotone_boundaries(boundary, mesh.vertices, labels,
                                        polycube_charts(boundary, mesh.vertices, labels))
                    .empty());
}

}  // namespace
}  // namespace sa
