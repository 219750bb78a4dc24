// The frame fields of ../shared/data/frame-fields through the seamless pipeline. Skips when the
// data folder is absent.
#include <gtest/gtest.h>

#include <filesystem>

#include "frontends/seamless/seamless_parameterization.h"
#include "geometry/io/frame_field_io.h"
#include "geometry/io/mesh_file.h"

namespace sa {
namespace {

// Directional's torus_twosings is that configuration: diagnosed before anything is optimized.
TEST(Seamless, DirectionalsTwoSingularityTorusIsDiagnosed) {
    const std::string folder = std::string(SA_DATA_DIR) + "/frame-fields/";
    if (!std::filesystem::exists(folder + "torus_twosings.rawfield"))
        GTEST_SKIP() << folder << " is absent";
    const MeshFile mesh = read_mesh_file(folder + "torus.obj");
    const FrameFieldFile field =
        read_frame_field(folder + "torus_twosings.rawfield", mesh.mesh.num_simplices());
    const SeamlessResult r =
        seamless_parameterization(mesh.mesh, FrameFieldInput{field.u, field.v, {}});
    EXPECT_FALSE(r.success);
    EXPECT_FALSE(r.infeasible.empty()) << r.message;
    EXPECT_EQ(r.singularities_before.size(), 2u);
    EXPECT_EQ(r.integrable.newton.num_steps(), 0) << "nothing should be optimized";
}

}  // namespace
}  // namespace sa
