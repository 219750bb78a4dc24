#include "frontends/polycube/polycube_verification.h"

#include <gtest/gtest.h>

#include <map>

#include "frontends/polycube/boundary_angle_sums.h"
#include "frontends/polycube/polycube_preparation.h"
#include "tests/fixtures/polycube_fixtures.h"

namespace sa {
namespace {

bool mentions(const PolycubeVerification& v, const std::string& part) {
    for (const std::string& f : v.failures) {
        if (f.find(part) != std::string::npos) return true;
    }
    return false;
}

// An L-shaped block of voxels is itself a PolyCube: its own positions pass.
TEST(PolycubeVerification, AValidPolycubePasses) {
    const PreparedPolycube p =
        prepare_polycube(testing::voxel_tetrahedra(testing::l_shape(), 2), "L", {});
    const PolycubeVerification v = verify_polycube(p.layout(), p.mesh.vertices, p.input_volume);
    EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
    EXPECT_EQ(v.quality.inverted, 0);
    EXPECT_NEAR(v.quality.conformal.max, 1.0, 1e-12);
    EXPECT_NEAR(v.volume_scale, 1.0, 1e-12);
    EXPECT_EQ(v.max_planarity, 0.0);
    EXPECT_EQ(v.polycube_edges, 18);  // 8 charts: 12 convex edges, 6 around the inner corner
    EXPECT_GT(v.shortest_edge, 0.2);
    EXPECT_NEAR(v.max_edge_angle_sum, 1.5 * M_PI, 1e-12);    // the inner, concave edge
    EXPECT_NEAR(v.max_vertex_angle_sum, 3.0 * M_PI, 1e-12);  // on the concave edge
    // Scaled, rotated about an axis by 90 degrees and moved: still a PolyCube; the distortion is
    // measured at the input's volume.
    Eigen::MatrixXd moved(p.mesh.num_vertices(), 3);
    moved.col(0) = -3.0 * p.mesh.vertices.col(1);
    moved.col(1) = 3.0 * p.mesh.vertices.col(0);
    moved.col(2) = 3.0 * p.mesh.vertices.col(2);
    moved.rowwise() += Eigen::RowVector3d(10, 0, -2);
    // The rotation sends +X faces to +Y: relabel by moving the labels with it.
    PreparedPolycube turned = p;
    for (int& label : turned.labels) {
        const int axis = label_axis(label), sign = label_sign(label);
        label = axis == 0 ? make_label(1, sign) : axis == 1 ? make_label(0, -sign) : label;
    }
    turned.charts = polycube_charts(turned.boundary, turned.mesh.vertices, turned.labels);
    const PolycubeVerification w = verify_polycube(turned.layout(), moved, turned.input_volume);
    EXPECT_TRUE(w.passed) << (w.failures.empty() ? "" : w.failures.front());
    EXPECT_NEAR(w.volume_scale, 1.0 / 3.0, 1e-12);
    EXPECT_NEAR(w.quality.isometric.max, 1.0, 1e-12);
}

TEST(PolycubeVerification, ABentChartAWrongSideAndAnInvertedTetFail) {
    const PreparedPolycube p =
        prepare_polycube(testing::voxel_tetrahedra({{0, 0, 0}}, 2), "cube", {});
    // The centre of the top face raised a little: its chart is no longer planar.
    Eigen::MatrixXd bent = p.mesh.vertices;
    Index centre = -1;
    for (Index v = 0; v < bent.rows(); ++v) {
        if ((bent.row(v) - Eigen::RowVector3d(0.5, 0.5, 1.0)).norm() < 1e-12) centre = v;
    }
    ASSERT_GE(centre, 0);
    bent(centre, 2) += 1e-3;
    PolycubeVerification v = verify_polycube(p.layout(), bent, p.input_volume);
    EXPECT_FALSE(v.passed);
    EXPECT_EQ(v.nonplanar_charts, 1);
    EXPECT_TRUE(mentions(v, "is not planar")) << v.failures.front();
    EXPECT_NEAR(v.max_planarity * v.diagonal, 1e-3, 1e-12);

    // The same map mirrored in x: every tetrahedron inverted; the Y and Z charts' area vectors
    // turn inwards (the X charts' keep their x component: they swapped sides).
    Eigen::MatrixXd mirrored = p.mesh.vertices;
    mirrored.col(0) *= -1.0;
    v = verify_polycube(p.layout(), mirrored, p.input_volume);
    EXPECT_EQ(v.quality.inverted, p.mesh.num_simplices());
    EXPECT_EQ(v.wrong_side_charts, 4);
    EXPECT_TRUE(mentions(v, "inverted"));
    EXPECT_TRUE(mentions(v, "faces away from"));

    // The centre vertex pushed through the bottom: the tetrahedra around it invert.
    Eigen::MatrixXd pushed = p.mesh.vertices;
    const Index middle = [&] {
        for (Index v = 0; v < pushed.rows(); ++v) {
            if ((pushed.row(v) - Eigen::RowVector3d(0.5, 0.5, 0.5)).norm() < 1e-12) return v;
        }
        return Index(-1);
    }();
    ASSERT_GE(middle, 0);
    pushed(middle, 2) = -0.2;
    v = verify_polycube(p.layout(), pushed, p.input_volume);
    EXPECT_GT(v.quality.inverted, 0);
    EXPECT_FALSE(v.passed);
}

TEST(PolycubeVerification, AFlattenedBoxHasZeroLengthEdges) {
    const PreparedPolycube p =
        prepare_polycube(testing::voxel_tetrahedra({{0, 0, 0}}, 1), "cube", {});
    Eigen::MatrixXd flat = p.mesh.vertices;
    flat.col(0).setZero();
    const PolycubeVerification v = verify_polycube(p.layout(), flat, p.input_volume);
    EXPECT_FALSE(v.passed);
    EXPECT_EQ(v.quality.degenerate, p.mesh.num_simplices());
    EXPECT_EQ(v.zero_length_edges, 4);  // the four edges along x
    EXPECT_TRUE(mentions(v, "has length 0"));
}

// A fan of six positive tetrahedra around the edge (0,0,0)-(0,0,1), open over 300 degrees at
// rest, mapped to 400 degrees: every tetrahedron keeps its orientation, but the fan overlaps
// itself at the boundary edge.
TEST(PolycubeVerification, AnOverlappingFanFailsTheAngleSums) {
    SimplicialMesh mesh;
    mesh.vertices.resize(9, 3);
    mesh.simplices.resize(6, 4);
    mesh.vertices.row(0) << 0, 0, 0;
    mesh.vertices.row(1) << 0, 0, 1;
    for (int m = 0; m <= 6; ++m) {
        const double a = 50.0 * m * M_PI / 180.0;
        mesh.vertices.row(2 + m) << std::cos(a), std::sin(a), 0.5;
    }
    for (int k = 0; k < 6; ++k) mesh.simplices.row(k) << 0, 1, 2 + k, 3 + k;
    for (Index t = 0; t < 6; ++t) {
        if (tet_orientation(mesh, t) < 0) std::swap(mesh.simplices(t, 2), mesh.simplices(t, 3));
    }
    const MeshTopology topology = mesh_topology(mesh, "fan");
    const TetBoundary boundary = tet_boundary(mesh, topology);
    const PolycubeCharts charts =
        polycube_charts(boundary, mesh.vertices, closest_axis_labels(boundary, mesh.vertices));
    const std::vector<BoundaryEdgeFan> fans = boundary_edge_fans(mesh, topology, boundary);
    const std::vector<BoundaryVertexStar> stars = boundary_vertex_stars(mesh, topology, boundary);
    Eigen::MatrixXd mapped = mesh.vertices;
    for (int m = 0; m <= 6; ++m) {
        const double a = (400.0 / 6.0) * m * M_PI / 180.0;
        mapped.row(2 + m) << std::cos(a), std::sin(a), 0.5 + 0.1 * m;
    }
    const PolycubeLayout layout{&mesh, &boundary, &charts, &fans, &stars};
    const double volume = tet_mesh_volume(mesh, mesh.vertices);
    const PolycubeVerification at_rest = verify_polycube(layout, mesh.vertices, volume);
    EXPECT_EQ(at_rest.edge_angle_violations, 0);
    EXPECT_NEAR(at_rest.max_edge_angle_sum, 300.0 * M_PI / 180.0, 1e-12);
    const PolycubeVerification v = verify_polycube(layout, mapped, volume);
    EXPECT_EQ(v.quality.inverted, 0);
    EXPECT_EQ(v.edge_angle_violations, 1);
    EXPECT_NEAR(v.max_edge_angle_sum, 400.0 * M_PI / 180.0, 1e-12);
    EXPECT_TRUE(mentions(v, "boundary edge (0, 1) has a dihedral-angle sum of 2.22 pi"))
        << v.failures.size();
    EXPECT_FALSE(v.passed);
}

TEST(BoundaryAngleSums, OfAVoxelShape) {
    const SimplicialMesh mesh = testing::voxel_tetrahedra(testing::l_shape(), 2);
    const MeshTopology topology = mesh_topology(mesh, "L");
    const TetBoundary boundary = tet_boundary(mesh, topology);
    const auto fans = boundary_edge_fans(mesh, topology, boundary);
    const auto stars = boundary_vertex_stars(mesh, topology, boundary);
    EXPECT_EQ(fans.size(), boundary.edges.size());
    Index boundary_vertices = 0;
    for (Index v = 0; v < mesh.num_vertices(); ++v) boundary_vertices += boundary.on_boundary[v];
    EXPECT_EQ(Index(stars.size()), boundary_vertices);
    // In multiples of pi / 4. Dihedral sums: pi inside faces, pi / 2 along convex edges, 3 pi / 2
    // along the concave one (two mesh edges). Solid angles: 2 pi inside faces, pi on convex edges,
    // 3 pi on the concave one, pi / 2 at the ten convex corners, 3 pi / 2 at the two others.
    std::map<long, int> edge_sums, vertex_sums;
    for (const double s : dihedral_angle_sums(fans, mesh.vertices)) {
        ++edge_sums[std::lround(s / (M_PI / 4))];
    }
    for (const double s : solid_angle_sums(stars, mesh.vertices)) {
        ++vertex_sums[std::lround(s / (M_PI / 4))];
    }
    EXPECT_EQ(edge_sums.size(), 3u);
    EXPECT_EQ(edge_sums[6], 2);
    EXPECT_EQ(vertex_sums.size(), 5u);
    EXPECT_EQ(vertex_sums[2], 10);
    EXPECT_EQ(vertex_sums[6], 2);
    EXPECT_EQ(vertex_sums[12], 1);
}

}  // namespace
}  // namespace sa
