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

#include "energies/subspace_point_energy.h"
#include "energies/vertex_copy_energies.h"
#include "frontends/cli/cli_support.h"
#include "frontends/cli/command_options.h"
#include "frontends/hex/grid_start.h"
#include "frontends/hex/hex_optimization.h"
#include "frontends/hex/hex_padding.h"
#include "frontends/hex/polycube_surface.h"
#include "frontends/polycube/polycube_planes.h"
#include "geometry/io/medit_io.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/tet_boundary.h"
#include "optim/derivative_check.h"
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

/// The unit cube's tetrahedra (n per side), its boundary, and `rest`: the cube moved by x ->
/// x + a sin(pi x)(y + z) e_x, which keeps every face in place but slides the points of the
/// y and z faces along x, unevenly: a PolyCube map (grid = n x) whose hexes have sheared
/// boundary faces.
struct SlidCube {
    SimplicialMesh mesh;
    TetBoundary boundary;
    Eigen::MatrixXd grid, rest;
};
SlidCube slid_cube(int n, double a) {
    SlidCube c;
    c.mesh = testing::voxel_tetrahedra({{0, 0, 0}}, n);
    c.boundary = tet_boundary(c.mesh, mesh_topology(c.mesh, "cube"));
    c.grid = c.mesh.vertices * double(n);
    c.rest = c.mesh.vertices;
    for (Index v = 0; v < c.rest.rows(); ++v) {
        const Eigen::Vector3d p = c.mesh.vertices.row(v).transpose();
        c.rest(v, 0) += a * std::sin(M_PI * p.x()) * (p.y() + p.z());
    }
    return c;
}

// Point location on the PolyCube's planes, and the closest rest point on a plane and on an edge.
TEST(PolycubeSurface, LocatesGridPointsAndProjectsRestPoints) {
    const SlidCube c = slid_cube(4, 0.2);
    const PolycubeSurface surface(c.boundary.triangles, c.grid, c.rest);
    EXPECT_EQ(surface.triangles_left_out(), 0);
    // A grid point on the face z = 0 lands where the map takes it; the tangent map is that of
    // x + a sin(pi x) y along x and y.
    const std::optional<SurfacePoint> at = surface.locate(2, Eigen::Vector3d(1.5, 2.5, 0.0));
    ASSERT_TRUE(at);
    EXPECT_NEAR(at->rest.z(), 0.0, 1e-15);
    EXPECT_NEAR(at->rest.y(), 2.5 / 4.0, 1e-12);
    EXPECT_NEAR(at->grid.x(), 1.5, 1e-12);
    EXPECT_NEAR(at->jacobian(1, 1), 0.25, 1e-12);
    EXPECT_EQ(at->jacobian.col(2).norm(), 0.0);
    // Outside the cube's face: nothing.
    EXPECT_FALSE(surface.locate(2, Eigen::Vector3d(4.5, 1.0, 0.0)));
    EXPECT_FALSE(surface.locate(2, Eigen::Vector3d(1.0, 1.0, 2.0)));  // no plane z = 2
    // A rest point above the face z = 0 returns to it, straight down.
    const std::optional<SurfacePoint> down =
        surface.closest(2, Eigen::Vector3d(2.0, 2.0, 0.0), Eigen::Vector3d(0.4, 0.6, 0.3), -1, 2.0);
    ASSERT_TRUE(down);
    EXPECT_LT((down->rest - Eigen::Vector3d(0.4, 0.6, 0.0)).norm(), 1e-12);
    // On the edge where z = 0 meets y = 0 (the line along x), it stays on the edge.
    const std::optional<SurfacePoint> edge =
        surface.closest(2, Eigen::Vector3d(2.0, 0.0, 0.0), Eigen::Vector3d(0.45, 0.1, 0.2), 1, 2.0);
    ASSERT_TRUE(edge);
    EXPECT_LT((edge->rest - Eigen::Vector3d(0.45, 0.0, 0.0)).norm(), 1e-12);
    EXPECT_NEAR(edge->grid.y(), 0.0, 1e-12);
    EXPECT_NEAR(edge->grid.z(), 0.0, 1e-12);
    EXPECT_THROW(PolycubeSurface(c.boundary.triangles, c.grid.leftCols(2), c.rest),
                 InvalidArgumentError);
}

// The energy of points in affine subspaces: derivatives by finite differences, and the value is
// the inner energy's at origin + basis q.
TEST(SubspacePointEnergy, DerivativesMatchFiniteDifferences) {
    SimplexEnergyOptions o;
    o.barrier_distortion = DistortionType::kConformal;
    VertexSimplexEnergy<3> corner(SimplexEnergy<3>(o, {1.0}), {Mat<3>::Identity()});
    std::vector<Vec<3>> origins = {Vec<3>(0, 0, 0), Vec<3>(1.1, 0.1, 0), Vec<3>(0.2, 0.9, 0.1),
                                   Vec<3>(0.1, 0.0, 1.0)};
    std::vector<Mat<3>> bases(4, Mat<3>::Identity());
    origins[0].setZero();                       // point 0 moves freely
    bases[1] << 1, 0, 0, 0.2, 1, 0, 0, 0, 0;    // point 1 on a plane
    bases[2] << 0.5, 0, 0, 0.5, 0, 0, 0, 0, 0;  // point 2 on a line
    bases[3].setZero();                         // point 3 fixed
    const SubspacePointEnergy<4, 3, VertexSimplexEnergy<3>> energy(corner, {{0, 1, 2, 3}}, origins,
                                                                   bases);
    Vec<12> q;
    q << 0.05, -0.02, 0.03, 0.1, -0.05, 0.0, 0.2, 0.0, 0.0, 0.0, 0.0, 0.0;
    const DerivativeCheck check = check_derivatives(energy, 0, q);
    EXPECT_TRUE(check.passes(1e-6)) << check.gradient_error << " " << check.hessian_error;
    Vec<12> x;
    for (int k = 0; k < 4; ++k) x.segment<3>(3 * k) = origins[k] + bases[k] * q.segment<3>(3 * k);
    EXPECT_EQ(energy.value(0, q), corner.value(0, x));
    EXPECT_THROW(
        (SubspacePointEnergy<4, 3, VertexSimplexEnergy<3>>(corner, {{0, 1, 2, 7}}, origins, bases)),
        InvalidArgumentError);
}

// On the slid cube the boundary faces of the extracted hexes are sheared: with the boundary
// fixed the worst hex stays sheared; sliding on the cube's surface brings every hex back to
// (nearly) a cube, every boundary vertex on its face and the cube's corners where they were.
TEST(HexOptimization, SlidingBoundaryUnshearsTheFacesOfASlidCube) {
    const SlidCube c = slid_cube(4, 0.15);
    const HexExtraction e = extract_hexes(c.mesh.simplices, c.grid, c.rest);
    const double extracted = hex_quality(e.mesh).min_scaled_jacobian;
    ASSERT_LT(extracted, 0.99);
    const HexOptimization fixed = optimize_hex_mesh(e.mesh, {});
    const PolycubeSurface surface(c.boundary.triangles, c.grid, c.rest);
    const HexOptimization slid =
        optimize_hex_mesh(e.mesh, {}, {}, {&surface, e.grid_points.cast<double>()});
    ASSERT_TRUE(fixed.ran && slid.ran) << fixed.message << " / " << slid.message;
    EXPECT_EQ(fixed.sliding_vertices, 0);
    EXPECT_EQ(slid.sliding_vertices, 98 - 8);  // the 98 boundary vertices but the 8 corners
    const double fixed_min = hex_quality(fixed.mesh).min_scaled_jacobian;
    const double slid_min = hex_quality(slid.mesh).min_scaled_jacobian;
    EXPECT_LT(fixed_min, 0.99) << extracted;
    EXPECT_GT(slid_min, 0.999) << fixed_min;
    const HexBoundary b = hex_boundary(e.mesh);
    for (Index v = 0; v < e.mesh.num_vertices(); ++v) {
        if (!b.on_boundary[v]) continue;
        const Eigen::RowVector3d p = slid.mesh.positions.row(v);
        const double to_face =
            std::min(p.cwiseAbs().minCoeff(), (p.array() - 1.0).abs().minCoeff());
        EXPECT_LT(to_face, 1e-12) << "vertex " << v;
        const Eigen::Vector3i g = e.grid_points.row(v).transpose();
        if (((g.array() == 0) || (g.array() == 4)).all()) {
            EXPECT_EQ(slid.mesh.positions.row(v), e.mesh.positions.row(v));
        }
    }
    EXPECT_THROW(optimize_hex_mesh(e.mesh, {}, {}, {&surface, Eigen::MatrixXd(3, 3)}),
                 InvalidArgumentError);
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
    ASSERT_EQ(Index(padded.source.size()), padded.mesh.num_vertices());
    for (Eigen::Index i = 0; i < b.quads.size(); ++i) {
        const Index v = b.quads.data()[i];
        EXPECT_GE(v, block.num_vertices());  // the copies, where their sources were
        EXPECT_EQ(padded.mesh.positions.row(v), block.positions.row(padded.source[v]));
    }
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
