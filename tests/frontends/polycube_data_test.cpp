// `sa polycube`'s preparation on tetrahedral meshes of ../shared/data whose computed labels
// admit no PolyCube map. Skips when the data folder is absent.
#include <gtest/gtest.h>

#include <filesystem>

#include "frontends/polycube/polycube_preparation.h"
#include "geometry/io/mesh_file.h"
#include "optim/errors.h"

namespace sa {
namespace {

class PolycubeNoMap : public ::testing::TestWithParam<const char*> {};

// The computed labels of these meshes leave tetrahedra that every map with planar charts
// flattens (decimated-knight: two -Z charts meet at a vertex; wrench-rest: a +X and a -X chart
// do), and no split repairs them: refused in the preparation, with the charts that meet, instead
// of a solve that runs to its time limit and fails.
TEST_P(PolycubeNoMap, ComputedLabelsWithFlatTetrahedraAreRefused) {
    const std::string path = std::string(SA_DATA_DIR) + "/" + GetParam();
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent";
    const SimplicialMesh mesh = read_mesh_file(path).mesh;
    try {
        prepare_polycube(mesh, path, PolycubeLabelInput{});
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(path + ": the computed labels admit no valid PolyCube map: "),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find(" meet at vertex "), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

INSTANTIATE_TEST_SUITE_P(Meshes, PolycubeNoMap,
                         ::testing::Values("tet/decimated-knight.mesh",
                                           "deform/wrench/wrench-rest.mesh"));

}  // namespace
}  // namespace sa
