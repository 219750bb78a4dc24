// Hex meshing through the PolyCube map (frontends/hex/): the planes' quantization, the
// extraction, the stages end to end and the `sa hex` command, on generated voxel shapes.
#include "frontends/hex/hex_meshing.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "frontends/cli/cli_support.h"
#include "frontends/cli/command_options.h"
#include "frontends/hex/grid_start.h"
#include "frontends/hex/hex_optimization.h"
#include "frontends/hex/hex_padding.h"
#include "frontends/polycube/polycube_planes.h"
#include "geometry/io/medit_io.h"
#include "optim/errors.h"
#include "tests/fixtures/voxel_meshes.h"

namespace sa {
namespace {

// A step one cell high: the bottom (z = 0), the step's top (0.3) and the top (2.0). The step is
// a PolyCube edge's extent, so it keeps a cell; without the separation it merges with the bottom.
TEST(PlaneQuantization, AStepKeepsOneCellAndMergesWithoutItsEdge) {
    const std::vector<double> z = {0.0, 0.3, 2.0};
    const std::vector<int> axis = {2, 2, 2};
    const PlaneQuantization kept = quantize_planes(z, axis, {{0, 1}}, 1.0);
    EXPECT_EQ(kept.position, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(kept.raised, 1);
    EXPECT_EQ(kept.distinct_positions[2], 3);
    EXPECT_EQ(kept.extent[2], 2);
    const PlaneQuantization merged = quantize_planes(z, axis, {}, 1.0);
    EXPECT_EQ(merged.position, (std::vector<int>{0, 0, 2}));
    EXPECT_EQ(merged.distinct_positions[2], 2);
}

// Two features closer than a cell, on an L-shape's x planes (0, 1.1, 1.3, 3): separated, the
// second is raised past the first and the planes above keep their order; the other axes are
// quantized on their own.
TEST(PlaneQuantization, CloseFeaturesStayApartOnlyWhenTheRuleSays) {
    const std::vector<double> c = {0.0, 1.1, 1.3, 3.0, 0.0, 2.0};
    const std::vector<int> axis = {0, 0, 0, 0, 1, 1};
    const PlaneQuantization apart = quantize_planes(c, axis, {{1, 2}, {0, 3}}, 1.0);
    EXPECT_EQ(apart.position, (std::vector<int>{0, 1, 2, 3, 0, 2}));
    const PlaneQuantization together = quantize_planes(c, axis, {{0, 3}}, 1.0);
    EXPECT_EQ(together.position, (std::vector<int>{0, 1, 1, 3, 0, 2}));
    // A coarse cell raises a chain of separations one cell at a time.
    const PlaneQuantization coarse = quantize_planes(c, axis, {{0, 1}, {1, 2}, {2, 3}}, 10.0);
    EXPECT_EQ(coarse.position, (std::vector<int>{0, 1, 2, 3, 0, 0}));
    EXPECT_THROW(quantize_planes(c, axis, {{2, 1}}, 1.0), InvalidArgumentError);
    EXPECT_THROW(quantize_planes(c, axis, {{0, 4}}, 1.0), InvalidArgumentError);
    EXPECT_THROW(quantize_planes(c, axis, {}, 0.0), InvalidArgumentError);
}

// A box whose planes move from 0 and 2.2 to 0 and 2 (each axis): the harmonic displacement of
// linear boundary values is linear, so the start is the box scaled exactly; the planes are at
// their integers.
TEST(GridStart, PlanesMoveAsAWholeAndTheInsideFollowsSmoothly) {
    const SimplicialMesh mesh = testing::voxel_tetrahedra({{0, 0, 0}}, 3);
    const PreparedPolycube p = prepare_polycube(mesh, "cube", PolycubeLabelInput{});
    const PolycubePlanes planes = polycube_planes(p.boundary, p.charts, p.mesh.num_vertices());
    ASSERT_EQ(planes.size(), 6);
    const Eigen::MatrixXd map = p.mesh.vertices * 2.2;
    std::vector<double> coordinates(planes.size(), 0.0);
    for (Index v = 0; v < p.mesh.num_vertices(); ++v)
        for (int a = 0; a < 3; ++a)
            if (planes.plane_of_vertex[v][a] >= 0)
                coordinates[planes.plane_of_vertex[v][a]] = map(v, a);
    const PlaneQuantization q = quantize_planes(coordinates, planes.axis, {}, 1.0);
    const Eigen::MatrixXd start =
        grid_start(p.mesh.simplices, map, planes.plane_of_vertex, coordinates, q);
    const double lowest = p.mesh.vertices.minCoeff(), highest = p.mesh.vertices.maxCoeff();
    const Eigen::MatrixXd expected =
        (p.mesh.vertices.array() - lowest) / (highest - lowest) * 2.0 + std::round(2.2 * lowest);
    EXPECT_LT((start - expected).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_THROW(
        grid_start(p.mesh.simplices, map.leftCols(2), planes.plane_of_vertex, coordinates, q),
        InvalidArgumentError);
}

// The identity map, scaled to grid units, gives one hex per grid cell of the shape, each a cube
// (scaled Jacobian 1) at its rest place.
TEST(HexExtraction, TheIdentityOfACubeAndOfAnLShapeGivesTheirCells) {
    for (const auto& [cells, per_unit, expected] :
         {std::tuple{std::vector<testing::Cell>{{0, 0, 0}}, 6, 216},
          std::tuple{testing::l_shape(), 2, 24}}) {
        const SimplicialMesh mesh = testing::voxel_tetrahedra(cells, 3);
        const HexExtraction e =
            extract_hexes(mesh.simplices, mesh.vertices * double(per_unit), mesh.vertices);
        ASSERT_EQ(e.mesh.num_hexes(), expected);
        EXPECT_EQ(e.cells_with_missing_corners, 0);
        const HexQuality q = hex_quality(e.mesh);
        EXPECT_EQ(q.inverted, 0);
        EXPECT_NEAR(q.min_scaled_jacobian, 1.0, 1e-12);
        EXPECT_NEAR(q.volume, double(cells.size()), 1e-12);
        EXPECT_TRUE(hex_boundary(e.mesh).closed());
        // Each vertex is its grid point mapped back.
        EXPECT_LT((e.mesh.positions * double(per_unit) - e.grid_points.cast<double>())
                      .cwiseAbs()
                      .maxCoeff(),
                  1e-12);
    }
    // Point location in a sheared map: the hexes land where the inverse map takes them.
    SimplicialMesh mesh = testing::voxel_tetrahedra({{0, 0, 0}}, 2);
    Eigen::MatrixXd grid = mesh.vertices * 4.0;
    Eigen::MatrixXd rest = mesh.vertices;
    rest.col(0) += 0.3 * rest.col(2);  // the rest shape is a sheared cube
    const HexExtraction e = extract_hexes(mesh.simplices, grid, rest);
    ASSERT_EQ(e.mesh.num_hexes(), 64);
    for (Index v = 0; v < e.mesh.num_vertices(); ++v) {
        const Eigen::Vector3d g = e.grid_points.row(v).cast<double>().transpose() / 4.0;
        EXPECT_NEAR(e.mesh.positions(v, 0), g.x() + 0.3 * g.z(), 1e-12);
    }
    EXPECT_THROW(extract_hexes(mesh.simplices, grid.leftCols(2), rest), InvalidArgumentError);
}

/// n^3 unit cubes.
HexMesh hex_block(int n) {
    const SimplicialMesh cube = testing::voxel_tetrahedra({{0, 0, 0}}, n);
    return extract_hexes(cube.simplices, cube.vertices * double(n), cube.vertices * double(n)).mesh;
}

// An inner vertex pushed through its neighbours inverts hexes; the optimization untangles their
// corners, then brings every hex back to a cube, the boundary untouched.
TEST(HexOptimization, UntanglesAnInvertedHexAndRestoresTheCubes) {
    HexMesh mesh = hex_block(4);
    const HexMesh original = mesh;
    Index inner = -1;
    for (Index v = 0; v < mesh.num_vertices() && inner < 0; ++v)
        if ((mesh.positions.row(v).array() == 1.0).all()) inner = v;  // (1, 1, 1)
    ASSERT_GE(inner, 0);
    mesh.positions.row(inner) << 2.6, 2.5, 2.7;
    ASSERT_GT(hex_quality(mesh).inverted, 0);
    const HexOptimization r = optimize_hex_mesh(mesh, {});
    ASSERT_TRUE(r.ran) << r.message;
    EXPECT_TRUE(r.untangled);
    const HexQuality q = hex_quality(r.mesh);
    EXPECT_EQ(q.inverted, 0);
    EXPECT_GT(q.min_scaled_jacobian, 0.999);
    EXPECT_LT((r.mesh.positions - original.positions).cwiseAbs().maxCoeff(), 1e-3);
    // The boundary stays where it was.
    const HexBoundary b = hex_boundary(mesh);
    for (Eigen::Index i = 0; i < b.quads.size(); ++i) {
        const Index v = b.quads.data()[i];
        EXPECT_EQ(r.mesh.positions.row(v), mesh.positions.row(v));
    }
    // Nothing inside to move: returned as given.
    const HexOptimization none = optimize_hex_mesh(hex_block(1), {});
    EXPECT_FALSE(none.ran);
    EXPECT_EQ(none.free_vertices, 0);
}

// A smooth warp of the inside (every hex valid) lowers the scaled Jacobian; the optimization
// raises its minimum and its mean.
TEST(HexOptimization, RaisesTheWorstScaledJacobianOfAWarpedBlock) {
    HexMesh mesh = hex_block(6);
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        const Eigen::Vector3d p = mesh.positions.row(v).transpose() / 6.0;
        const double bump =
            std::sin(M_PI * p.x()) * std::sin(M_PI * p.y()) * std::sin(M_PI * p.z());
        mesh.positions(v, 0) += 1.2 * bump;
        mesh.positions(v, 2) += 0.8 * bump;
    }
    const HexQuality before = hex_quality(mesh);
    ASSERT_EQ(before.inverted, 0);
    const HexOptimization r = optimize_hex_mesh(mesh, {});
    ASSERT_TRUE(r.ran) << r.message;
    EXPECT_FALSE(r.untangled);
    const HexQuality after = hex_quality(r.mesh);
    EXPECT_GT(after.min_scaled_jacobian, before.min_scaled_jacobian + 0.1);
    EXPECT_GT(after.mean_scaled_jacobian, before.mean_scaled_jacobian);
}

// Padding a block of 2^3 cubes adds one hex per boundary quad (24), keeps the boundary closed
// and where it was, and leaves no hex corner with its four vertices on the boundary.
TEST(HexPadding, AddsALayerUnderTheBoundary) {
    const HexMesh block = hex_block(2);
    const HexPadding padded = pad_boundary(block, 0.5);
    EXPECT_EQ(padded.added_hexes, 24);
    ASSERT_EQ(padded.mesh.num_hexes(), 32);
    const HexQuality q = hex_quality(padded.mesh);
    EXPECT_EQ(q.inverted, 0);
    EXPECT_NEAR(q.volume, 8.0, 1e-12);
    const HexBoundary b = hex_boundary(padded.mesh);
    EXPECT_TRUE(b.closed());
    EXPECT_EQ(b.quads.rows(), 24);
    const std::vector<unsigned char>& on_boundary = b.on_boundary;
    for (Eigen::Index i = 0; i < b.quads.size(); ++i)
        EXPECT_GE(b.quads.data()[i], block.num_vertices());  // the copies
    for (Index h = 0; h < padded.mesh.num_hexes(); ++h) {
        for (int c = 0; c < 8; ++c) {
            bool free = !on_boundary[padded.mesh.hexes(h, c)];
            for (const int k : kHexCornerEdges[c]) free |= !on_boundary[padded.mesh.hexes(h, k)];
            EXPECT_TRUE(free) << h << " " << c;
        }
    }
    // The old boundary moved in by half an edge: the inner block spans [0.5, 1.5].
    EXPECT_NEAR(padded.mesh.positions.topRows(block.num_vertices()).minCoeff(), 0.5, 1e-12);
    EXPECT_THROW(pad_boundary(block, 0.0), InvalidArgumentError);

    // A corner of the block pushed inside: its corner tetrahedron, all four vertices on the
    // boundary, is inverted, which only padding can repair; the padded block has none.
    EXPECT_EQ(boundary_locked_inverted_corners(block, hex_boundary(block)), 0);
    HexMesh pushed = block;
    for (Index v = 0; v < pushed.num_vertices(); ++v)
        if (pushed.positions.row(v).norm() == 0.0) pushed.positions.row(v) << 1.2, 1.2, 1.2;
    // The pushed corner, and the corners at its three neighbours, whose edges reach it.
    EXPECT_EQ(boundary_locked_inverted_corners(pushed, hex_boundary(pushed)), 4);
    const HexMesh padded_pushed = pad_boundary(pushed, 0.5).mesh;
    EXPECT_EQ(boundary_locked_inverted_corners(padded_pushed, hex_boundary(padded_pushed)), 0);
}

PreparedPolycube prepared_shape(const SimplicialMesh& mesh) {
    return prepare_polycube(mesh, "generated", PolycubeLabelInput{});
}

// End to end on a bent L-shape: every stage verifies, the grid PolyCube's planes are integers,
// the count is near the target and the hexes are valid on the bent shape.
TEST(HexMeshing, ABentLShapeGivesAVerifiedHexMesh) {
    const PreparedPolycube prepared =
        prepared_shape(testing::bent(testing::voxel_tetrahedra(testing::l_shape(), 2), 0.12));
    HexMeshingOptions options;
    options.hexes = 200;
    const HexMeshing r = hex_mesh_from_polycube(prepared, options);
    ASSERT_TRUE(r.success()) << r.message;
    EXPECT_TRUE(r.polycube.success);
    EXPECT_TRUE(r.grid_polycube.success);
    EXPECT_GT(r.verification.hexes, 100);
    EXPECT_LT(r.verification.hexes, 400);
    EXPECT_EQ(r.verification.quality.inverted, 0);
    EXPECT_GT(r.verification.quality.min_scaled_jacobian, 0.3);
    EXPECT_GT(r.verification.quality.mean_scaled_jacobian, 0.9);
    EXPECT_NEAR(r.verification.volume_ratio, 1.0, 0.05);
    EXPECT_LT(r.verification.distance_to_input, 1e-9);  // hex boundary vertices on the input
    EXPECT_LT(r.verification.distance_from_input, 0.05);
    // The boundary vertices of the grid PolyCube lie on integer planes.
    for (Index v = 0; v < prepared.mesh.num_vertices(); ++v) {
        if (!prepared.boundary.on_boundary[v]) continue;
        double nearest = 1.0;
        for (int a = 0; a < 3; ++a) {
            const double x = r.grid_polycube.positions(v, a);
            nearest = std::min(nearest, std::abs(x - std::round(x)));
        }
        EXPECT_LT(nearest, 1e-9) << v;
    }
    // A hex size instead of a count: a cell of 0.25 gives 48 cells on the unbent volume of 3.
    HexMeshingOptions sized;
    sized.hex_size = 0.25;
    const HexMeshing s = hex_mesh_from_polycube(prepared, sized);
    ASSERT_TRUE(s.success()) << s.message;
    EXPECT_GT(s.verification.hexes, 100);
    EXPECT_LT(s.verification.hexes, 300);
    HexMeshingOptions bad;
    bad.hexes = 0;
    EXPECT_THROW(hex_mesh_from_polycube(prepared, bad), InvalidArgumentError);
}

namespace fs = std::filesystem;

/// The hexes of a Medit file as `sa hex` writes it.
HexMesh read_hexes(const std::string& path) {
    std::ifstream in(path);
    std::string word;
    HexMesh mesh;
    while (in >> word) {
        if (word == "Vertices") {
            Index n = 0;
            in >> n;
            mesh.positions.resize(n, 3);
            for (Index v = 0; v < n; ++v) {
                int ref = 0;
                in >> mesh.positions(v, 0) >> mesh.positions(v, 1) >> mesh.positions(v, 2) >> ref;
            }
        } else if (word == "Hexahedra") {
            Index n = 0;
            in >> n;
            mesh.hexes.resize(n, 8);
            for (Index h = 0; h < n; ++h) {
                for (int c = 0; c < 8; ++c) {
                    in >> mesh.hexes(h, c);
                    --mesh.hexes(h, c);
                }
                int ref = 0;
                in >> ref;
            }
        }
    }
    return mesh;
}

TEST(HexCommand, EndToEndOnAGeneratedMeshAndItsChecks) {
    const fs::path dir = fs::temp_directory_path() / ("sa_hex_command_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    auto path = [&](const std::string& name) { return (dir / name).string(); };
    const SimplicialMesh mesh =
        testing::bent(testing::voxel_tetrahedra(testing::l_shape(), 2), 0.1);
    write_medit(path("L.mesh"), mesh.vertices, mesh.simplices);

    auto run = [&](const std::vector<std::string>& words) {
        cli::HexArguments arguments;
        cli::parse_command_line(words, arguments);
        return cli::run_hex_command(arguments);
    };
    ::testing::internal::CaptureStdout();
    const int status = run({"--mesh", path("L.mesh"), "--hexes", "150", "--out", path("h.mesh"),
                            "--polycube", path("p.mesh"), "--vtu", path("h.vtu"), "--report",
                            path("h.json"), "--no-png", "--quiet"});
    const std::string out = ::testing::internal::GetCapturedStdout();
    ASSERT_EQ(status, cli::kExitVerified) << out;
    for (const char* name : {"h.mesh", "h.vtu", "h.json", "p.mesh", "p.rest.mesh", "p.flags"})
        EXPECT_TRUE(fs::exists(path(name))) << name;
    // Read back: the same checks pass on the file's positions.
    const HexMesh hexes = read_hexes(path("h.mesh"));
    ASSERT_GT(hexes.num_hexes(), 50);
    const HexQuality q = hex_quality(hexes);
    EXPECT_EQ(q.inverted, 0);
    EXPECT_TRUE(hex_boundary(hexes).closed());
    std::ifstream report_file(path("h.json"));
    const nlohmann::json report = nlohmann::json::parse(report_file);
    EXPECT_EQ(report["success"], true);
    EXPECT_EQ(report["verification"]["hexes"].get<Index>(), hexes.num_hexes());
    EXPECT_NEAR(report["verification"]["scaled_jacobian"]["min"].get<double>(),
                q.min_scaled_jacobian, 1e-9);

    // Bad options: one line naming the option, before any work.
    auto message = [&](const std::vector<std::string>& words) -> std::string {
        try {
            run(words);
        } catch (const Error& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_NE(message({"--mesh", path("L.mesh"), "--out", path("x.obj")}).find("--out"),
              std::string::npos);
    EXPECT_NE(message({"--mesh", path("L.mesh"), "--out", path("x.mesh"), "--hexes", "0"})
                  .find("--hexes 0"),
              std::string::npos);
    EXPECT_NE(message({"--mesh", path("L.mesh"), "--out", path("x.mesh"), "--hexes", "10",
                       "--hex-size", "0.1"})
                  .find("one or the other"),
              std::string::npos);
    EXPECT_NE(message({"--mesh", path("L.mesh"), "--out", path("x.mesh"), "--hex-size", "-1"})
                  .find("--hex-size -1"),
              std::string::npos);
    EXPECT_NE(message({"--mesh", path("none.mesh"), "--out", path("x.mesh")}).find("none.mesh"),
              std::string::npos);
    EXPECT_FALSE(fs::exists(path("x.mesh")));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sa
