#include "frontends/deform/deform_start.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "geometry/mesh/mesh_generators.h"
#include "optim/errors.h"
#include "tests/fixtures/bar_deformation.h"

namespace sa {
namespace {

TEST(DeformStart, RigidMotionIsReproducedWithoutDistortion) {
    const SimplicialMesh mesh = grid_tetrahedra(6, 2, 2);
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(1.3, Eigen::Vector3d(0.2, 1.0, -0.4).normalized()).toRotationMatrix();
    HandleTargets h;
    for (Index v : {0, 6, 20, 62}) {
        h.handles.push_back(v);
    }
    h.targets.resize(4, 3);
    for (int k = 0; k < 4; ++k)
        h.targets.row(k) = (R * mesh.vertices.row(h.handles[k]).transpose()).transpose();
    std::vector<std::string> lines;
    ArapOptions options;
    options.tolerance = 1e-13;
    const DeformStart start =
        deform_start(mesh, h, options, [&](const std::string& line) { lines.push_back(line); });
    EXPECT_TRUE(start.arap.converged);
    EXPECT_EQ(start.quality.inverted, 0);
    EXPECT_EQ(start.quality.degenerate, 0);
    EXPECT_NEAR(start.quality.isometric.max, 1.0, 1e-9);
    EXPECT_NEAR(start.quality.volumetric.max, 1.0, 1e-9);
    EXPECT_EQ(start.handle_error, 0.0);
    ASSERT_FALSE(lines.empty());
    EXPECT_NE(lines.back().find("ARAP start:"), std::string::npos) << lines.back();
    EXPECT_NE(lines.back().find("0 inverted"), std::string::npos) << lines.back();
    EXPECT_EQ(start.arap.positions.size(), 0);  // moved to start.positions
    EXPECT_EQ(start.positions.rows(), mesh.num_vertices());
}

TEST(DeformStart, CountsTheSimplicesTheStartInverts) {
    // A grid whose one corner handle is pulled through the opposite side: ARAP folds triangles.
    const SimplicialMesh grid = grid_triangles(8, 8);
    HandleTargets h;
    h.handles = {0, 8, 72, 80};
    h.targets.resize(4, 2);
    h.targets << 1.6, 1.6, 1, 0, 0, 1, 1, 1;  // vertex 0 beyond vertex 80's corner
    const DeformStart start = deform_start(grid, h);
    EXPECT_GT(start.quality.inverted, 0);
    std::size_t flagged = 0;
    for (const SimplexQuality& s : start.quality.per_simplex) flagged += s.inverted;
    EXPECT_EQ(flagged, std::size_t(start.quality.inverted));
    EXPECT_NE(describe(start).find(std::to_string(start.quality.inverted) + " inverted"),
              std::string::npos);
}

TEST(DeformStart, BarPosesStartWithTheirHandlesInPlace) {
    BarDeformationOptions small;
    small.length_cells = 15;
    small.cross_cells = 3;
    for (BarPose pose : {BarPose::kBend, BarPose::kTwist, BarPose::kTranslate}) {
        const BarDeformation bar = bar_deformation(pose, small);
        const DeformStart start = deform_start(bar.mesh, {bar.handles, bar.targets});
        EXPECT_EQ(start.handle_error, 0.0) << bar.name;
        EXPECT_GT(start.arap.iterations, 0) << bar.name;
        EXPECT_LT(start.arap.energy, start.arap.initial_energy) << bar.name;
    }
}

TEST(DeformStart, SurfacesAreRejected) {
    const SimplicialMesh torus = torus_triangles(8, 6);
    HandleTargets h;
    h.handles = {0};
    h.targets = Eigen::MatrixXd::Zero(1, 3);
    EXPECT_THROW(deform_start(torus, h), InvalidArgumentError);
}

}  // namespace
}  // namespace sa
