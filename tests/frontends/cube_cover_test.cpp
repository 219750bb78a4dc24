#include "frontends/polycube/cube_cover.h"

#include <gtest/gtest.h>

#include <array>

#include "frontends/polycube/polycube_planes.h"
#include "geometry/mesh/mesh_generators.h"
#include "tests/fixtures/polycube_fixtures.h"

namespace sa {
namespace {

struct Covered {
    SimplicialMesh mesh;
    TetBoundary boundary;
    PolycubeCharts charts;
};

Covered make(const SimplicialMesh& mesh) {
    Covered s{mesh, tet_boundary(mesh, mesh_topology(mesh, "test")), {}};
    s.charts =
        polycube_charts(s.boundary, mesh.vertices, closest_axis_labels(s.boundary, mesh.vertices));
    return s;
}

// sum_T vol_T |grad_T x_axis - e_axis|^2, computed from the Jacobians of the map.
double energy(const SimplicialMesh& mesh, const Eigen::MatrixXd& x, int axis) {
    double sum = 0.0;
    for (Index t = 0; t < mesh.num_simplices(); ++t) {
        Eigen::Matrix3d rest, image;
        for (int k = 0; k < 3; ++k) {
            rest.col(k) = (mesh.vertices.row(mesh.simplices(t, k + 1)) -
                           mesh.vertices.row(mesh.simplices(t, 0)))
                              .transpose();
            image.col(k) =
                (x.row(mesh.simplices(t, k + 1)) - x.row(mesh.simplices(t, 0))).transpose();
        }
        const Eigen::Matrix3d J = image * rest.inverse();
        Eigen::RowVector3d g = J.row(axis);
        g[axis] -= 1.0;
        sum += std::abs(rest.determinant()) / 6.0 * g.squaredNorm();
    }
    return sum;
}

double signed_volume(const Eigen::MatrixXd& x, const SimplicialMesh& mesh, Index t) {
    Eigen::Matrix3d e;
    for (int k = 0; k < 3; ++k) {
        e.col(k) = (x.row(mesh.simplices(t, k + 1)) - x.row(mesh.simplices(t, 0))).transpose();
    }
    return e.determinant();
}

TEST(CubeCover, AnAxisAlignedBoxMapsToItself) {
    const Covered s = make(testing::voxel_tetrahedra({{0, 0, 0}, {1, 0, 0}}, 2));
    const CubeCover cover = cube_cover_map(s.mesh, s.boundary, s.charts);
    EXPECT_LT((cover.positions - s.mesh.vertices).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT(cover.energy.maxCoeff(), 1e-20);
}

TEST(CubeCover, ChartsArePlanarAndTheInteriorIsTheLeastSquaresSolution) {
    const Covered s = make(testing::bent(testing::voxel_tetrahedra(testing::l_shape(), 3), 0.06));
    ASSERT_EQ(s.charts.size(), 8);
    const CubeCover cover = cube_cover_map(s.mesh, s.boundary, s.charts);
    // Every vertex of a chart at the chart's coordinate along its axis.
    for (int c = 0; c < s.charts.size(); ++c) {
        const int axis = label_axis(s.charts.label[c]);
        for (const Index b : s.charts.members[c]) {
            for (int i = 0; i < 3; ++i) {
                EXPECT_NEAR(cover.positions(s.boundary.triangles(b, i), axis),
                            cover.chart_coordinate[c], 1e-12);
            }
        }
    }
    // Opposite charts in the right order, and the map has not folded this gentle shape.
    for (int c = 0; c < s.charts.size(); ++c) {
        const int axis = label_axis(s.charts.label[c]);
        const double rest = s.mesh.vertices(s.boundary.triangles(s.charts.members[c][0], 0), axis);
        EXPECT_NEAR(cover.chart_coordinate[c], rest, 0.15);
    }
    for (Index t = 0; t < s.mesh.num_simplices(); ++t) {
        EXPECT_GT(signed_volume(cover.positions, s.mesh, t), 0.0) << t;
    }
    // The energy is the one minimized, and moving any free vertex along an axis raises it (a
    // vertex inside a PolyCube edge along that axis is not free: see the next test).
    std::vector<std::vector<int>> chart_of_vertex(s.mesh.num_vertices());
    for (int c = 0; c < s.charts.size(); ++c) {
        for (const Index b : s.charts.members[c]) {
            for (int i = 0; i < 3; ++i) chart_of_vertex[s.boundary.triangles(b, i)].push_back(c);
        }
    }
    const PolycubePlanes planes = polycube_planes(s.boundary, s.charts, s.mesh.num_vertices());
    std::array<std::vector<unsigned char>, 3> on_edge;
    for (auto& flags : on_edge) flags.assign(s.mesh.num_vertices(), 0);
    for (const PolycubeEdgeOrder& e :
         polycube_edge_orders(s.boundary, s.charts, planes, s.mesh.vertices)) {
        for (const Index v : e.vertices) on_edge[e.axis][v] = 1;
    }
    for (int axis = 0; axis < 3; ++axis) {
        const double e0 = energy(s.mesh, cover.positions, axis);
        EXPECT_NEAR(cover.energy[axis], e0, 1e-12);
        for (Index v = 0; v < s.mesh.num_vertices(); v += 7) {
            bool on_axis_chart = false;
            for (const int c : chart_of_vertex[v])
                on_axis_chart |= label_axis(s.charts.label[c]) == axis;
            if (on_axis_chart || on_edge[axis][v]) continue;
            for (const double h : {1e-3, -1e-3}) {
                Eigen::MatrixXd moved = cover.positions;
                moved(v, axis) += h;
                EXPECT_GT(energy(s.mesh, moved, axis), e0) << v;
            }
        }
    }
}

// A block whose top steps up (a wall facing -X, rest height 0.2) between two slopes falling away
// from the step: the least-squares planes of the two top charts come out in the wrong order (the
// lower one above the upper one), which folds the wall. The cube cover ties the planes of the
// wall's edges at half their rest extent instead.
TEST(CubeCover, KeepsPolyCubeEdgesInRestOrder) {
    SimplicialMesh mesh = grid_tetrahedra(20, 4, 4);  // [0, 1] x [0, 0.2] x [0, 0.2]
    auto height = [](double x) {
        if (x < 0.45) return 1.0 + 0.9 * (0.45 - x);
        if (x < 0.55) return 1.0 + 0.2 * (x - 0.45) / 0.1;
        return 1.2 - 0.9 * (x - 0.55);
    };
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        mesh.vertices(v, 1) *= 2.5;
        mesh.vertices(v, 2) *= 5.0 * height(mesh.vertices(v, 0));
    }
    const Covered s = make(mesh);
    ASSERT_EQ(s.charts.size(), 8);
    const CubeCover cover = cube_cover_map(s.mesh, s.boundary, s.charts);
    EXPECT_GE(cover.lengthened_edges, 1);
    EXPECT_EQ(cover.unordered_edges, 0);
    EXPECT_EQ(cover.collapsed_edges, 0);
    // The two top charts (+Z): the one left of the step below the one right of it.
    double left = kInfinity, right = kInfinity;
    for (int c = 0; c < s.charts.size(); ++c) {
        if (s.charts.label[c] != make_label(2, +1)) continue;
        const double x = s.mesh.vertices(s.boundary.triangles(s.charts.members[c][0], 0), 0);
        (x < 0.5 ? left : right) = cover.chart_coordinate[c];
    }
    ASSERT_TRUE(std::isfinite(left) && std::isfinite(right));
    EXPECT_GE(right - left, 0.5 * 0.2 - 1e-9);
    Index folded = 0;
    for (Index t = 0; t < s.mesh.num_simplices(); ++t)
        folded += signed_volume(cover.positions, s.mesh, t) <= 0.0;
    EXPECT_EQ(folded, 0);
}

// The vertices inside a PolyCube edge lie on it in their order between its corners, spaced as
// their rest arc length: on the step below and on the bent L-shape.
TEST(CubeCover, SpacesEdgeVerticesByArcLengthBetweenTheCorners) {
    for (const SimplicialMesh& mesh :
         {testing::bent(testing::voxel_tetrahedra(testing::l_shape(), 3), 0.06),
          testing::bent(grid_tetrahedra(6, 3, 2), 0.1)}) {
        const Covered s = make(mesh);
        const CubeCover cover = cube_cover_map(s.mesh, s.boundary, s.charts);
        const PolycubePlanes planes = polycube_planes(s.boundary, s.charts, s.mesh.num_vertices());
        int inner = 0;
        for (const PolycubeEdgeOrder& e :
             polycube_edge_orders(s.boundary, s.charts, planes, s.mesh.vertices)) {
            double length = 0.0;
            std::vector<double> along{0.0};
            for (std::size_t k = 1; k < e.vertices.size(); ++k) {
                length +=
                    (s.mesh.vertices.row(e.vertices[k]) - s.mesh.vertices.row(e.vertices[k - 1]))
                        .norm();
                along.push_back(length);
            }
            const double from = cover.positions(e.from, e.axis), to = cover.positions(e.to, e.axis);
            ASSERT_GT(to, from);
            for (std::size_t k = 1; k + 1 < e.vertices.size(); ++k, ++inner) {
                EXPECT_NEAR(cover.positions(e.vertices[k], e.axis),
                            from + (to - from) * along[k] / length, 1e-12);
            }
        }
        EXPECT_GT(inner, 0);
    }
}

TEST(CubeCover, KeepsTheVolumeWeightedMean) {
    SimplicialMesh mesh = testing::bent(testing::voxel_tetrahedra({{0, 0, 0}}, 3), 0.08);
    mesh.vertices.rowwise() += Eigen::RowVector3d(5.0, -3.0, 2.0);
    const Covered s = make(mesh);
    const CubeCover cover = cube_cover_map(s.mesh, s.boundary, s.charts);
    Eigen::RowVector3d rest_mean = Eigen::RowVector3d::Zero(), mapped_mean = rest_mean;
    double total = 0.0;
    for (Index t = 0; t < mesh.num_simplices(); ++t) {
        const double w = std::abs(signed_volume(mesh.vertices, mesh, t));
        for (int k = 0; k < 4; ++k) {
            rest_mean += w * mesh.vertices.row(mesh.simplices(t, k));
            mapped_mean += w * cover.positions.row(mesh.simplices(t, k));
        }
        total += 4 * w;
    }
    EXPECT_LT(((rest_mean - mapped_mean) / total).norm(), 1e-12);
}

}  // namespace
}  // namespace sa
