#include "frontends/polycube/polycube_splits.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "optim/errors.h"
#include "tests/fixtures/polycube_fixtures.h"

namespace sa {
namespace {

double volume(const SimplicialMesh& mesh, Index t) {
    Eigen::Matrix3d e;
    for (int k = 0; k < 3; ++k) {
        e.col(k) =
            (mesh.vertices.row(mesh.simplices(t, k + 1)) - mesh.vertices.row(mesh.simplices(t, 0)))
                .transpose();
    }
    return e.determinant() / 6.0;
}

double total_volume(const SimplicialMesh& mesh) {
    double sum = 0.0;
    for (Index t = 0; t < mesh.num_simplices(); ++t) sum += volume(mesh, t);
    return sum;
}

std::vector<int> closest_flags(const SimplicialMesh& mesh) {
    const TetBoundary boundary = tet_boundary(mesh, mesh_topology(mesh, "test"));
    return facet_flags(boundary, mesh.num_simplices(),
                       closest_axis_labels(boundary, mesh.vertices));
}

/// Orients every tetrahedron positively.
SimplicialMesh oriented(SimplicialMesh mesh) {
    for (Index t = 0; t < mesh.num_simplices(); ++t) {
        if (volume(mesh, t) < 0) std::swap(mesh.simplices(t, 1), mesh.simplices(t, 2));
    }
    return mesh;
}

// A unit cube of six Kuhn tetrahedra whose top face is folded up along its diagonal (0,0,1) -
// (1,1,1), with one more tetrahedron under the fold: its four vertices are on the top chart, and
// the edge under the fold is an interior edge with both ends there.
SimplicialMesh folded_top() {
    SimplicialMesh mesh;
    mesh.vertices.resize(8, 3);
    // Corners (x, y, z) of the cube; x is flipped in the Kuhn paths below so that the top
    // diagonal of the cube's tetrahedra is b-d = (1,0,1)-(0,1,1), lowered to z = 0.8.
    auto corner = [](int i, int j, int k) { return (k * 2 + j) * 2 + i; };
    for (int k = 0; k < 2; ++k) {
        for (int j = 0; j < 2; ++j) {
            for (int i = 0; i < 2; ++i) {
                double z = k;
                if (k == 1 && i != j) z = 0.8;
                mesh.vertices.row(corner(i, j, k)) << i, j, z;
            }
        }
    }
    const std::array<std::array<int, 3>, 6> orders = {
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    std::vector<std::array<Index, 4>> tets;
    for (const auto& order : orders) {
        std::array<int, 3> u = {0, 0, 0};  // (1 - x, y, z)
        std::array<Index, 4> tet{};
        tet[0] = corner(1 - u[0], u[1], u[2]);
        for (int step = 0; step < 3; ++step) {
            ++u[order[step]];
            tet[step + 1] = corner(1 - u[0], u[1], u[2]);
        }
        tets.push_back(tet);
    }
    tets.push_back({corner(0, 0, 1), corner(1, 0, 1), corner(1, 1, 1), corner(0, 1, 1)});
    mesh.simplices.resize(Index(tets.size()), 4);
    for (std::size_t t = 0; t < tets.size(); ++t) {
        for (int k = 0; k < 4; ++k) mesh.simplices(Index(t), k) = tets[t][k];
    }
    return oriented(mesh);
}

// A unit cube with a flat pyramid on one of its two top triangles: the pyramid's tetrahedron has
// all four vertices on the top chart and all six edges on the boundary; only a face split of its
// interior facet repairs it.
SimplicialMesh pyramid_top() {
    SimplicialMesh mesh = testing::voxel_tetrahedra({{0, 0, 0}}, 1);
    const TetBoundary boundary = tet_boundary(mesh, mesh_topology(mesh, "cube"));
    Index top = -1;
    for (Index b = 0; b < boundary.size(); ++b) {
        bool up = true;
        for (int i = 0; i < 3; ++i) up = up && mesh.vertices(boundary.triangles(b, i), 2) == 1.0;
        if (up) top = b;
    }
    const Eigen::RowVector3d apex = (mesh.vertices.row(boundary.triangles(top, 0)) +
                                     mesh.vertices.row(boundary.triangles(top, 1)) +
                                     mesh.vertices.row(boundary.triangles(top, 2))) /
                                        3.0 +
                                    Eigen::RowVector3d(0, 0, 0.1);
    mesh.vertices.conservativeResize(9, 3);
    mesh.vertices.row(8) = apex;
    mesh.simplices.conservativeResize(7, 4);
    mesh.simplices.row(6) << 8, boundary.triangles(top, 0), boundary.triangles(top, 1),
        boundary.triangles(top, 2);
    return oriented(mesh);
}

void expect_split_well(const SimplicialMesh& before, const SimplicialMesh& after,
                       const std::vector<int>& flags, const PolycubeSplitReport& report) {
    EXPECT_EQ(report.after.total(), 0);
    EXPECT_EQ(count_squashed_elements(after, flags).total(), 0);
    EXPECT_EQ(after.num_vertices(), before.num_vertices() + report.vertices_added);
    EXPECT_EQ(after.num_simplices(), before.num_simplices() + report.tets_added);
    EXPECT_EQ(after.vertices.topRows(before.num_vertices()), before.vertices);
    for (Index t = 0; t < after.num_simplices(); ++t) EXPECT_GT(volume(after, t), 1e-6) << t;
    EXPECT_NEAR(total_volume(after), total_volume(before), 1e-12);
    // The labels followed the splits: the geometry did not change, so they are still the
    // closest axes of the new boundary triangles.
    EXPECT_EQ(flags, closest_flags(after));
}

TEST(PolycubeSplits, AFoldedTopIsRepairedByAnEdgeSplit) {
    const SimplicialMesh mesh = folded_top();
    std::vector<int> flags = closest_flags(mesh);
    const SquashedElements squashed = count_squashed_elements(mesh, flags);
    EXPECT_EQ(squashed.tets, 1);
    EXPECT_EQ(squashed.interior_edges, 1);
    SimplicialMesh split = mesh;
    const PolycubeSplitReport report = split_squashed_elements(split, flags, "folded");
    EXPECT_EQ(report.before.tets, 1);
    EXPECT_EQ(report.edge_splits, 1);
    EXPECT_EQ(report.face_splits, 0);
    EXPECT_EQ(report.vertices_added, 1);
    expect_split_well(mesh, split, flags, report);
}

TEST(PolycubeSplits, APyramidIsRepairedByAFaceSplit) {
    const SimplicialMesh mesh = pyramid_top();
    std::vector<int> flags = closest_flags(mesh);
    const SquashedElements squashed = count_squashed_elements(mesh, flags);
    EXPECT_EQ(squashed.tets, 1);
    EXPECT_EQ(squashed.interior_edges, 0);
    SimplicialMesh split = mesh;
    const PolycubeSplitReport report = split_squashed_elements(split, flags, "pyramid");
    EXPECT_EQ(report.edge_splits, 0);
    EXPECT_EQ(report.face_splits, 1);
    EXPECT_EQ(report.tets_added, 4);  // the pyramid and the tetrahedron under it, in three each
    expect_split_well(mesh, split, flags, report);
    // Unsplit tetrahedra keep their index and vertices.
    Index kept = 0;
    for (Index t = 0; t < mesh.num_simplices(); ++t)
        kept += mesh.simplices.row(t) == split.simplices.row(t);
    EXPECT_EQ(kept, mesh.num_simplices() - 2);
}

// The top of a cube labelled -X, one chart with the -X side: boundary triangles of the side
// faces at the top corner of -X then have their three vertices on that chart, and boundary edges
// there have both ends on it.
TEST(PolycubeSplits, BoundaryTrianglesAndEdgesOnAnotherChartAreSplit) {
    const SimplicialMesh mesh = testing::voxel_tetrahedra({{0, 0, 0}}, 2);
    const TetBoundary boundary = tet_boundary(mesh, mesh_topology(mesh, "cube"));
    std::vector<int> labels = closest_axis_labels(boundary, mesh.vertices);
    for (int& label : labels) {
        if (label == 4) label = 1;
    }
    std::vector<int> flags = facet_flags(boundary, mesh.num_simplices(), labels);
    const SquashedElements squashed = count_squashed_elements(mesh, flags);
    EXPECT_GE(squashed.boundary_triangles, 1);
    EXPECT_GE(squashed.boundary_edges, 1);
    SimplicialMesh split = mesh;
    const PolycubeSplitReport report = split_squashed_elements(split, flags, "cube");
    EXPECT_EQ(report.after.total(), 0);
    for (Index t = 0; t < split.num_simplices(); ++t) EXPECT_GT(volume(split, t), 1e-6);
    EXPECT_NEAR(total_volume(split), 1.0, 1e-12);
    // The top is still labelled -X, every other triangle by its own side.
    const TetBoundary after = tet_boundary(split, mesh_topology(split, "split"));
    const std::vector<int> carried =
        boundary_labels_from_flags(after, split.num_simplices(), flags, "split");
    const std::vector<int> closest = closest_axis_labels(after, split.vertices);
    const Eigen::MatrixXd area = boundary_area_vectors(after, split.vertices);
    double top = 0.0;
    for (Index b = 0; b < after.size(); ++b) {
        if (closest[b] == 4) {
            EXPECT_EQ(carried[b], 1);
            top += area.row(b).norm();
        } else {
            EXPECT_EQ(carried[b], closest[b]);
        }
    }
    EXPECT_NEAR(top, 1.0, 1e-12);
}

TEST(PolycubeSplits, ACleanMeshIsUnchanged) {
    const SimplicialMesh mesh =
        testing::bent(testing::voxel_tetrahedra(testing::l_shape(), 2), 0.02);
    std::vector<int> flags = closest_flags(mesh);
    const std::vector<int> before = flags;
    SimplicialMesh split = mesh;
    const PolycubeSplitReport report = split_squashed_elements(split, flags, "L");
    EXPECT_EQ(report.before.total(), 0);
    EXPECT_EQ(report.vertices_added, 0);
    EXPECT_EQ(split.simplices, mesh.simplices);
    EXPECT_EQ(flags, before);
}

// A box [0,2] x [0,1] x [0,1] whose top is twisted by 10 degrees, as two triangular prisms
// over the halves of its bottom, A B C and A C D (A = (0,0), C = (2,1)), that split their shared
// diagonal face differently (A0-C1 and A1-C0): the sliver tetrahedron (A0, A1, C0, C1) between
// them has positive rest volume, but its vertices lie on two parallel PolyCube edges (the
// corners -X-Y and +X+Y): every map with planar charts flattens it. A face split cannot help
// (two of its children hold A0, A1 and one vertex of C, or the reverse, and have opposite
// volumes wherever the new vertex is); the split of the right diagonal can.
SimplicialMesh twisted_box() {
    SimplicialMesh mesh;
    mesh.vertices.resize(8, 3);
    const std::array<Eigen::Vector2d, 4> corners = {Eigen::Vector2d(0, 0), Eigen::Vector2d(2, 0),
                                                    Eigen::Vector2d(2, 1), Eigen::Vector2d(0, 1)};
    const double angle = 10.0 * M_PI / 180.0;
    const Eigen::Vector2d centre(1.0, 0.5);
    const Eigen::Matrix2d turn = Eigen::Rotation2Dd(angle).toRotationMatrix();
    for (int k = 0; k < 4; ++k) {
        mesh.vertices.row(k) << corners[k].x(), corners[k].y(), 0.0;  // A0 B0 C0 D0
        const Eigen::Vector2d top = centre + turn * (corners[k] - centre);
        mesh.vertices.row(4 + k) << top.x(), top.y(), 1.0;  // A1 B1 C1 D1
    }
    enum { A0, B0, C0, D0, A1, B1, C1, D1 };
    mesh.simplices.resize(7, 4);
    // Prism A B C, its face A-C split by A0-C1.
    mesh.simplices.row(0) << A0, B0, C0, C1;
    mesh.simplices.row(1) << A0, B0, C1, B1;
    mesh.simplices.row(2) << A0, B1, C1, A1;
    // Prism A C D, its face A-C split by A1-C0.
    mesh.simplices.row(3) << A0, C0, D0, A1;
    mesh.simplices.row(4) << C0, D0, A1, C1;
    mesh.simplices.row(5) << D0, A1, C1, D1;
    // The sliver between the two diagonals.
    mesh.simplices.row(6) << A0, A1, C0, C1;
    return oriented(mesh);
}

TEST(PolycubeSplits, ATetrahedronOnTwoParallelPolycubeEdgesIsSplitAcross) {
    const SimplicialMesh mesh = twisted_box();
    for (Index t = 0; t < mesh.num_simplices(); ++t) ASSERT_GT(volume(mesh, t), 1e-3) << t;
    std::vector<int> flags = closest_flags(mesh);
    const SquashedElements squashed = count_squashed_elements(mesh, flags);
    EXPECT_EQ(squashed.tets, 0);
    EXPECT_EQ(squashed.interior_edges, 0);
    EXPECT_EQ(squashed.boundary_edges, 0);
    EXPECT_EQ(squashed.boundary_triangles, 0);
    EXPECT_EQ(squashed.flattened_tets, 1);
    SimplicialMesh split = mesh;
    const PolycubeSplitReport report = split_squashed_elements(split, flags, "twisted");
    EXPECT_EQ(report.before.flattened_tets, 1);
    EXPECT_EQ(report.face_splits, 0);
    EXPECT_EQ(report.edge_splits, 1);
    expect_split_well(mesh, split, flags, report);
    // The new vertex is the midpoint of one of the two diagonals A0-C1 and A1-C0.
    ASSERT_EQ(split.num_vertices(), 9);
    const Eigen::RowVector3d m = split.vertices.row(8);
    const double to_a0c1 = (m - 0.5 * (mesh.vertices.row(0) + mesh.vertices.row(6))).norm();
    const double to_a1c0 = (m - 0.5 * (mesh.vertices.row(4) + mesh.vertices.row(2))).norm();
    EXPECT_LT(std::min(to_a0c1, to_a1c0), 1e-12);
}

// Two tetrahedra a b c p and a c b q on their common facet a b c, every other facet on the
// boundary: a b p (+Z) and c b q (-Z) are two charts that meet at vertex b only, and so are
// b c p (+X) and a q b (+X); a p c and a c q are one +Y chart. Charts of one axis that share a
// vertex lie in one plane, so all five vertices are on the Z plane and both tetrahedra are flat
// in every PolyCube of these labels. No split can lift them (every edge is on the boundary, and
// a facet's new vertex is on that plane in the planes' model): the report names them.
TEST(PolycubeSplits, TetrahedraFlatOnEveryPolycubeAreReported) {
    SimplicialMesh mesh;
    mesh.vertices.resize(5, 3);
    mesh.vertices << 0, 0, 0,  // a
        1, 0, 0,               // b
        0, 1, 0,               // c
        0.3, 0.3, 1,           // p
        0.3, 0.3, -1;          // q
    mesh.simplices.resize(2, 4);
    mesh.simplices << 0, 1, 2, 3,  // a b c p
        0, 2, 1, 4;                // a c b q
    ASSERT_GT(volume(mesh, 0), 0.0);
    ASSERT_GT(volume(mesh, 1), 0.0);
    // Facets in kTetFacetCorners' order: {1,2,3}, {0,3,2}, {0,1,3}, {0,2,1} (the last: a b c).
    std::vector<int> flags = {0, 2, 4, -1,   // b c p +X, a p c +Y, a b p +Z
                              5, 0, 2, -1};  // c b q -Z, a q b +X, a c q +Y
    const SquashedElements squashed = count_squashed_elements(mesh, flags);
    EXPECT_EQ(squashed.tets, 0);
    EXPECT_EQ(squashed.interior_edges, 0);
    EXPECT_EQ(squashed.boundary_edges, 0);
    EXPECT_EQ(squashed.boundary_triangles, 0);
    EXPECT_EQ(squashed.flattened_tets, 2);
    SimplicialMesh split = mesh;
    const PolycubeSplitReport report = split_squashed_elements(split, flags, "bipyramid");
    EXPECT_EQ(report.after.flattened_tets, 2);
    EXPECT_EQ(report.flat_tets, (std::vector<Index>{0, 1}));
    EXPECT_EQ(report.vertices_added, 0);
    EXPECT_EQ(split.simplices, mesh.simplices);
}

}  // namespace
}  // namespace sa
