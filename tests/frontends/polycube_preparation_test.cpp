#include "frontends/polycube/polycube_preparation.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>

#include "frontends/polycube/polycube_output.h"
#include "geometry/io/medit_io.h"
#include "geometry/io/obj_io.h"
#include "geometry/io/polycube_labels_io.h"
#include "geometry/io/vtk_io.h"
#include "optim/errors.h"
#include "tests/fixtures/polycube_fixtures.h"

namespace sa {
namespace {

namespace fs = std::filesystem;

class PolycubePreparation : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("sa_polycube_" + std::to_string(getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

std::string message(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST_F(PolycubePreparation, ComputedLabels) {
    const SimplicialMesh mesh =
        testing::bent(testing::voxel_tetrahedra(testing::l_shape(), 3), 0.02);
    std::vector<std::string> lines;
    const PreparedPolycube p =
        prepare_polycube(mesh, "L", {}, [&](const std::string& l) { lines.push_back(l); });
    EXPECT_EQ(p.label_source, "computed");
    ASSERT_TRUE(p.cleanup.has_value());
    EXPECT_TRUE(p.cleanup->clean);
    EXPECT_FALSE(p.convention.has_value());
    EXPECT_EQ(p.output_sign, FlagSign::kOutward);
    EXPECT_EQ(p.charts.size(), 8);
    EXPECT_EQ(p.splits.before.total(), 0);
    EXPECT_EQ(p.mesh.simplices, mesh.simplices);
    EXPECT_EQ(p.fans.size(), p.boundary.edges.size());
    EXPECT_GT(p.stars.size(), 0u);
    // `mesh` at unit scale: the input times 2^-scale_exponent, its bounding-box diagonal in [1, 2).
    EXPECT_EQ(p.scale_exponent, scale_exponent(mesh.vertices));
    EXPECT_NEAR(std::ldexp(p.input_volume, 3 * p.scale_exponent),
                tet_mesh_volume(mesh, mesh.vertices), 1e-15);
    // The bent L turned a little faces the axes better; either labelling has 8 charts. The
    // bend moves its corners' angles off 90 degrees: a distortion floor a little above 1.
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_NE(lines[0].find("orientation: turned by"), std::string::npos) << lines[0];
    EXPECT_NE(lines[1].find("labels by closest axis, 8 charts"), std::string::npos) << lines[1];
    EXPECT_NE(lines[2].find("8 charts; squashed: 0 tetrahedra"), std::string::npos) << lines[2];
    EXPECT_NE(lines[3].find("every valid PolyCube map of these labels has conformal distortion >="),
              std::string::npos)
        << lines[3];
    EXPECT_GT(p.angle_bound.bound, 1.0);
    EXPECT_LT(p.angle_bound.bound, 1.5);
    ASSERT_TRUE(p.orientation.has_value());
    ASSERT_EQ(p.rest_positions().rows(), mesh.num_vertices());
    EXPECT_EQ(p.rest_positions(), mesh.vertices);
}

// Turned by 45 degrees about z, the L's walls face diagonals; turned back onto the axes, its
// labels are the L's own 8 charts. The rest mesh of the map is the turned copy, and
// rest_positions() gives the input's frame back.
TEST_F(PolycubePreparation, ComputedLabelsAreTakenInTheOrientationThatFacesTheAxes) {
    const SimplicialMesh axis_aligned = testing::voxel_tetrahedra(testing::l_shape(), 2);
    const Eigen::Matrix3d r =
        Eigen::AngleAxisd(M_PI / 4.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    SimplicialMesh mesh = axis_aligned;
    mesh.vertices = axis_aligned.vertices * r.transpose();
    const PreparedPolycube p = prepare_polycube(mesh, "L", {});
    ASSERT_TRUE(p.orientation.has_value());
    EXPECT_NEAR(p.orientation->angle_degrees, 45.0, 1e-3);
    EXPECT_EQ(p.charts.size(), 8);
    EXPECT_TRUE(p.non_monotone.empty());
    EXPECT_NEAR(p.orientation->energy, 1.0, 1e-6);
    // The input's vertices come first, then those of any splits.
    const Index n = mesh.num_vertices();
    ASSERT_GE(p.mesh.num_vertices(), n);
    EXPECT_LT((p.in_input_units(p.mesh.vertices.topRows(n)) -
               mesh.vertices * p.orientation->rotation.transpose())
                  .cwiseAbs()
                  .maxCoeff(),
              1e-15);
    ASSERT_EQ(p.rest_positions().rows(), p.mesh.num_vertices());
    EXPECT_EQ(p.rest_positions().topRows(n), mesh.vertices);

    PolycubeLabelInput own_axes;
    own_axes.orient = false;
    const PreparedPolycube kept = prepare_polycube(mesh, "L", own_axes);
    EXPECT_FALSE(kept.orientation.has_value() && kept.orientation->angle_degrees > 0.0);
    ASSERT_GE(kept.mesh.num_vertices(), n);
    EXPECT_EQ(kept.in_input_units(kept.mesh.vertices.topRows(n)), mesh.vertices);
}

TEST_F(PolycubePreparation, FlagsInTheirOwnConventionAreWrittenBackInIt) {
    const SimplicialMesh mesh = testing::voxel_tetrahedra(testing::l_shape(), 2);
    const PreparedPolycube computed = prepare_polycube(mesh, "L", {});
    std::vector<int> inward = computed.output_flags();
    for (int& f : inward) {
        if (f >= 0) f ^= 1;
    }
    write_facet_flags(path("L.flags"), inward);
    PolycubeLabelInput input;
    input.flags = path("L.flags");
    const PreparedPolycube p = prepare_polycube(mesh, "L", input);
    EXPECT_EQ(p.labels, computed.labels);
    ASSERT_TRUE(p.convention.has_value());
    EXPECT_EQ(p.convention->inward, p.boundary.size());
    EXPECT_EQ(p.output_sign, FlagSign::kInward);
    EXPECT_EQ(p.output_flags(), inward);
    EXPECT_EQ(p.label_source, path("L.flags"));
}

TEST_F(PolycubePreparation, SurfaceLabelsTransfer) {
    const SimplicialMesh mesh = testing::voxel_tetrahedra(testing::l_shape(), 2);
    const PreparedPolycube computed = prepare_polycube(mesh, "L", {});
    write_obj(path("boundary.obj"), mesh.vertices, computed.boundary.triangles);
    std::string labels;
    for (const int l : computed.labels) labels += std::to_string(l) + "\n";
    std::ofstream(path("labeling.txt")) << labels;
    PolycubeLabelInput input;
    input.labels = path("labeling.txt");
    input.surface = path("boundary.obj");
    const PreparedPolycube p = prepare_polycube(mesh, "L", input);
    EXPECT_EQ(p.labels, computed.labels);
    EXPECT_EQ(p.output_sign, FlagSign::kOutward);
}

TEST_F(PolycubePreparation, BadInputIsRejectedInOneLine) {
    const SimplicialMesh mesh = testing::voxel_tetrahedra({{0, 0, 0}}, 1);
    PolycubeLabelInput half;
    half.labels = path("labeling.txt");
    EXPECT_NE(message([&] { prepare_polycube(mesh, "cube", half); }).find("need both"),
              std::string::npos);
    SimplicialMesh triangles;
    triangles.vertices = mesh.vertices;
    triangles.simplices = Eigen::MatrixXi(1, 3);
    triangles.simplices << 0, 1, 2;
    EXPECT_NE(message([&] {
                  prepare_polycube(triangles, "t.obj", {});
              }).find("t.obj: a PolyCube map needs a tetrahedral mesh"),
              std::string::npos);
    std::ofstream(path("short.flags")) << "0 1 2\n";
    PolycubeLabelInput short_flags;
    short_flags.flags = path("short.flags");
    const std::string text = message([&] { prepare_polycube(mesh, "cube", short_flags); });
    EXPECT_NE(text.find("short.flags: 3 labels, expected 24"), std::string::npos) << text;
    EXPECT_EQ(text.find('\n'), std::string::npos);
    // Every boundary facet +X: one chart that cannot be planar.
    std::vector<int> all_x(24, -1);
    const TetBoundary boundary = tet_boundary(mesh, mesh_topology(mesh, "cube"));
    for (Index b = 0; b < boundary.size(); ++b) all_x[boundary.tet_facet[b]] = 0;
    write_facet_flags(path("x.flags"), all_x);
    PolycubeLabelInput x;
    x.flags = path("x.flags");
    EXPECT_NE(message([&] { prepare_polycube(mesh, "cube", x); }).find("cannot be planar"),
              std::string::npos);
}

// Two cubes side by side whose tetrahedra split the face between them along different diagonals:
// they share its four vertices, not its triangles, and the "boundary" runs through the inside.
TEST_F(PolycubePreparation, ANonConformingMeshIsNamedAsSuch) {
    const SimplicialMesh a = testing::voxel_tetrahedra({{0, 0, 0}}, 1);
    SimplicialMesh b = a;  // shifted by +1 in x and mirrored in y: the other diagonal at x = 1
    b.vertices.col(0).array() += 1.0;
    b.vertices.col(1) = (1.0 - b.vertices.col(1).array()).matrix();
    b.simplices.col(1).swap(b.simplices.col(2));  // positive again after the mirror
    SimplicialMesh both;
    std::map<std::array<double, 3>, Index> index;
    std::vector<Eigen::Vector3d> points;
    std::vector<std::array<Index, 4>> tets;
    for (const SimplicialMesh* m : {&a, static_cast<const SimplicialMesh*>(&b)}) {
        for (Index t = 0; t < m->num_simplices(); ++t) {
            std::array<Index, 4> tet{};
            for (int k = 0; k < 4; ++k) {
                const Eigen::Vector3d p = m->vertices.row(m->simplices(t, k)).transpose();
                const auto [it, inserted] =
                    index.emplace(std::array{p.x(), p.y(), p.z()}, Index(points.size()));
                if (inserted) points.push_back(p);
                tet[k] = it->second;
            }
            tets.push_back(tet);
        }
    }
    both.vertices.resize(Index(points.size()), 3);
    for (std::size_t v = 0; v < points.size(); ++v) both.vertices.row(Index(v)) = points[v];
    both.simplices.resize(Index(tets.size()), 4);
    for (std::size_t t = 0; t < tets.size(); ++t) {
        for (int k = 0; k < 4; ++k) both.simplices(Index(t), k) = tets[t][k];
    }
    ASSERT_EQ(both.num_vertices(), 12);
    const std::string text = message([&] { prepare_polycube(both, "two.ele", {}); });
    EXPECT_NE(text.find("two.ele: the boundary is not a closed manifold surface"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("non-conforming"), std::string::npos);
    EXPECT_EQ(text.find('\n'), std::string::npos);
    // Conforming, the same two cubes are prepared.
    EXPECT_NO_THROW(prepare_polycube(testing::voxel_tetrahedra({{0, 0, 0}, {1, 0, 0}}, 1), "two",
                                     PolycubeLabelInput{}));
}

// A solid at 1e100 or 1e-100 is prepared as at 1 (its areas and volumes would overflow or
// underflow): the same labels and charts, the same rest mesh of the map up to the power of two,
// and its outputs in its own units.
TEST_F(PolycubePreparation, ExtremeScalesArePreparedAsAtUnitScale) {
    const SimplicialMesh mesh =
        testing::bent(testing::voxel_tetrahedra(testing::l_shape(), 2), 0.02);
    const PreparedPolycube unit = prepare_polycube(mesh, "L", {});
    for (const double scale : {1e100, 1e-100}) {
        SCOPED_TRACE(scale);
        SimplicialMesh scaled = mesh;
        scaled.vertices *= scale;
        const PreparedPolycube p = prepare_polycube(scaled, "L", {});
        EXPECT_EQ(p.labels, unit.labels);
        EXPECT_EQ(p.charts.size(), unit.charts.size());
        EXPECT_EQ(p.mesh.simplices, unit.mesh.simplices);
        // Both at unit scale, apart by what is left of `scale` after the powers of two.
        const double left = std::ldexp(scale, unit.scale_exponent - p.scale_exponent);
        EXPECT_GT(left, 0.5);
        EXPECT_LT(left, 2.0);
        EXPECT_TRUE(p.mesh.vertices.isApprox(left * unit.mesh.vertices, 1e-14));
        EXPECT_NEAR(p.angle_bound.bound, unit.angle_bound.bound, 1e-12);
        EXPECT_EQ(p.rest_positions().topRows(mesh.num_vertices()), scaled.vertices);
        EXPECT_TRUE(p.in_input_units(p.mesh.vertices)
                        .isApprox(scale * unit.in_input_units(unit.mesh.vertices), 1e-14));
    }
}

TEST_F(PolycubePreparation, OutputsReadBack) {
    const SimplicialMesh mesh = testing::voxel_tetrahedra(testing::l_shape(), 2);
    const PreparedPolycube p = prepare_polycube(mesh, "L", {});
    Eigen::MatrixXd mapped = 2.0 * p.mesh.vertices;
    const PolycubeVerification v = verify_polycube(p.layout(), mapped, p.input_volume);
    ASSERT_TRUE(v.passed);
    const std::string out = path("L.mesh");
    EXPECT_EQ(polycube_rest_path(out), path("L.rest.mesh"));
    EXPECT_EQ(polycube_flags_path(out), path("L.flags"));
    EXPECT_THROW(polycube_rest_path(path("L.vtu")), InvalidArgumentError);
    write_polycube_meshes(out, p, mapped);
    const MeshFile map = read_medit(out), rest = read_medit(path("L.rest.mesh"));
    EXPECT_EQ(map.mesh.simplices, p.mesh.simplices);
    EXPECT_EQ(rest.mesh.simplices, p.mesh.simplices);
    EXPECT_TRUE(map.mesh.vertices.isApprox(p.in_input_units(mapped), 1e-15));
    EXPECT_TRUE(rest.mesh.vertices.isApprox(mesh.vertices, 1e-15));
    EXPECT_EQ(read_facet_flags(path("L.flags"), p.mesh.num_simplices()), p.output_flags());
    write_polycube_vtu(path("L.vtu"), p, mapped, v);
    const MeshFile vtu = read_vtu(path("L.vtu"));
    EXPECT_EQ(vtu.mesh.num_simplices(), p.mesh.num_simplices());
}

}  // namespace
}  // namespace sa
