// Handles and targets of ../shared/data/deform read as `sa deform` reads them, and the ARAP
// start on one case. Skips when the data folder is absent.
#include <gtest/gtest.h>

#include <filesystem>

#include "frontends/deform/deform_start.h"
#include "geometry/io/mesh_file.h"

namespace sa {
namespace {

std::string deform_path(const std::string& name, const std::string& suffix) {
    return std::string(SA_DATA_DIR) + "/deform/" + name + "/" + name + suffix;
}

class DeformData : public ::testing::TestWithParam<const char*> {};

// The handles and the rows of _init.node at them: every handle in range, the targets those rows.
TEST_P(DeformData, HandlesAndTargetsFromTheInitialShape) {
    const std::string name = GetParam();
    const std::string rest = deform_path(name, "_rest.node");
    if (!std::filesystem::exists(rest)) GTEST_SKIP() << rest << " is absent";
    const SimplicialMesh mesh = read_mesh_file(rest).mesh;
    const HandleTargets h = read_handle_targets(
        deform_path(name, "_handles.txt"), deform_path(name, "_init.node"), mesh.num_vertices(), 3);
    ASSERT_FALSE(h.handles.empty());
    const Eigen::MatrixXd init = read_mesh_file(deform_path(name, "_init.node")).mesh.vertices;
    for (std::size_t k = 0; k < h.handles.size(); ++k)
        ASSERT_EQ(h.targets.row(k), init.row(h.handles[k])) << k;
}

INSTANTIATE_TEST_SUITE_P(Cases, DeformData,
                         ::testing::Values("untwist", "stretch", "botijo", "rabbit"));

// stretch (20,480 tetrahedra, 578 handles): the start keeps its handles and folds nothing.
TEST(DeformDataStart, StretchStartsUnfolded) {
    const std::string rest = deform_path("stretch", "_rest.node");
    if (!std::filesystem::exists(rest)) GTEST_SKIP() << rest << " is absent";
    const SimplicialMesh mesh = read_mesh_file(rest).mesh;
    const HandleTargets h =
        read_handle_targets(deform_path("stretch", "_handles.txt"),
                            deform_path("stretch", "_init.node"), mesh.num_vertices(), 3);
    const DeformStart start = deform_start(mesh, h);
    EXPECT_TRUE(start.arap.converged) << start.arap.stop;
    EXPECT_EQ(start.quality.inverted, 0);
    EXPECT_EQ(start.handle_error, 0.0);
    EXPECT_LT(start.arap.energy, start.arap.initial_energy);
}

}  // namespace
}  // namespace sa
