#include "frontends/polycube/polycube_terms.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>
#include <span>

#include "frontends/polycube/boundary_angle_sums.h"
#include "frontends/polycube/polycube_planes.h"
#include "tests/fixtures/polycube_fixtures.h"

namespace sa {
namespace {

/// vec(A) once per tetrahedron of an A-form element of `count` tetrahedra.
Eigen::VectorXd repeated(const Mat<3>& A, int count) {
    Eigen::VectorXd x(9 * count);
    for (int k = 0; k < count; ++k) x.segment<9>(9 * k) = Eigen::Map<const Vec<9>>(A.data());
    return x;
}

/// The positions of a vertex-form element's vertices, one after the other.
Eigen::VectorXd gathered(const Eigen::MatrixXd& positions, std::span<const Index> vertices) {
    Eigen::VectorXd x(3 * vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i)
        x.segment<3>(3 * Eigen::Index(i)) = positions.row(vertices[i]).transpose();
    return x;
}

class PolycubeTerms : public ::testing::Test {
  protected:
    // A voxel L is its own PolyCube: at rest every planarity row vanishes.
    PreparedPolycube p =
        prepare_polycube(testing::voxel_tetrahedra(testing::l_shape(), 2), "L", {});
};

TEST_F(PolycubeTerms, PlanarityVanishesOnThePolycubeAndNotWhenTurned) {
    const PlanarityElements a = planarity_elements(p);
    const PlanarityVertexElements v = planarity_vertex_elements(p);
    ASSERT_EQ(Index(a.rows.size()), p.boundary.size());
    ASSERT_EQ(Index(v.rows.size()), p.boundary.size());
    const LinearConstraintEnergy<9, 2> energy(a.rows), vertex_energy(v.rows);
    const Mat<3> turned = Eigen::AngleAxisd(0.2, Vec<3>(1, 1, 1).normalized()).toRotationMatrix();
    for (Index e = 0; e < p.boundary.size(); ++e) {
        EXPECT_EQ(a.tet[e], p.boundary.tet(e));
        EXPECT_LT(energy.value(e, Vec<9>(repeated(Mat<3>::Identity(), 1))), 1e-30);
        EXPECT_GT(energy.value(e, Vec<9>(repeated(turned, 1))), 1e-4);
        EXPECT_LT(vertex_energy.value(e, Vec<9>(gathered(p.mesh.vertices, v.vertices[e]))), 1e-30);
        Eigen::MatrixXd rotated = p.mesh.vertices * turned.transpose();
        EXPECT_GT(vertex_energy.value(e, Vec<9>(gathered(rotated, v.vertices[e]))), 1e-4);
    }
}

TEST_F(PolycubeTerms, PlanesAndEdgesOfAnL) {
    const PolycubePlanes planes = polycube_planes(p.boundary, p.charts, p.mesh.num_vertices());
    EXPECT_EQ(planes.size(), 8);  // the L prism's faces: no two of one axis share a vertex
    std::map<int, int> by_planes;
    for (Index v = 0; v < p.mesh.num_vertices(); ++v) {
        int count = 0;
        for (const int plane : planes.plane_of_vertex[v]) count += plane >= 0;
        EXPECT_EQ(count > 0, bool(p.boundary.on_boundary[v])) << v;
        ++by_planes[count];
    }
    EXPECT_EQ(by_planes[3], 12);  // the L prism's corners
    // On PolyCube edges between corners: the top and bottom loops of the L are 8 units long, 2
    // mesh edges a unit, with 6 corners: 10 vertices each; each of the 6 vertical edges has its
    // midpoint.
    EXPECT_EQ(by_planes[2], 10 + 10 + 6);
    // 18 PolyCube edges, each between two corners on distinct planes, in rest order.
    const std::vector<PolycubeEdgeOrder> orders =
        polycube_edge_orders(p.boundary, p.charts, planes, p.mesh.vertices);
    EXPECT_EQ(orders.size(), 18u);
    for (const PolycubeEdgeOrder& e : orders) {
        EXPECT_NE(e.from_plane, e.to_plane);
        EXPECT_GT(e.rest_extent, 0.0);
        EXPECT_NEAR(e.rest_extent, p.mesh.vertices(e.to, e.axis) - p.mesh.vertices(e.from, e.axis),
                    1e-15);
        EXPECT_EQ(planes.plane_of_vertex[e.from][e.axis], e.from_plane);
    }
}

// At the rest map (A = I, vertices at rest) the A-form and the vertex form of each barrier give
// the same value, 1 / (limit - the angle sum measured from the positions).
TEST_F(PolycubeTerms, AngleBarriersAtRestAgreeAcrossForms) {
    const std::vector<double> edge_sums = dihedral_angle_sums(p.fans, p.mesh.vertices);
    std::map<std::array<Index, 2>, double> expected;
    for (std::size_t f = 0; f < p.fans.size(); ++f) {
        expected[p.fans[f].edge] = 1.0 / (2 * M_PI - edge_sums[f]);
    }
    // One element per boundary edge, in the order of the fans, in either form.
    const auto a_form = dihedral_sum_elements(p);
    const auto vertex_form = dihedral_sum_vertex_elements(p);
    ASSERT_EQ(a_form.items.size(), Index(p.fans.size()));
    ASSERT_EQ(vertex_form.items.size(), Index(p.fans.size()));
    for (std::size_t f = 0; f < p.fans.size(); ++f) {
        const Index e = Index(f);
        EXPECT_EQ(a_form.items[e][0], p.fans[f].tets[0]);
        EXPECT_NEAR(
            a_form.energy.value(e, repeated(Mat<3>::Identity(), int(p.fans[f].tets.size()))),
            expected[p.fans[f].edge], 1e-12);
        const std::span<const Index> vertices = vertex_form.items[e];
        const double at_edge = expected[{vertices[0], vertices[1]}];
        EXPECT_NEAR(vertex_form.energy.value(e, gathered(p.mesh.vertices, vertices)), at_edge,
                    1e-12);
    }

    const std::vector<double> vertex_sums = solid_angle_sums(p.stars, p.mesh.vertices);
    const auto star_a_form = solid_angle_sum_elements(p);
    const auto star_vertex_form = solid_angle_sum_vertex_elements(p);
    ASSERT_EQ(star_a_form.items.size(), Index(p.stars.size()));
    ASSERT_EQ(star_vertex_form.items.size(), Index(p.stars.size()));
    for (std::size_t s = 0; s < p.stars.size(); ++s) {
        const Index e = Index(s);
        const double expected_v = 1.0 / (4 * M_PI - vertex_sums[s]);
        EXPECT_EQ(star_a_form.items[e][0], p.stars[s].tets[0]);
        EXPECT_NEAR(
            star_a_form.energy.value(e, repeated(Mat<3>::Identity(), int(p.stars[s].tets.size()))),
            expected_v, 1e-12);
        EXPECT_EQ(star_vertex_form.items[e][0], p.stars[s].vertex);
        EXPECT_NEAR(
            star_vertex_form.energy.value(e, gathered(p.mesh.vertices, star_vertex_form.items[e])),
            expected_v, 1e-12);
    }
}

// Every boundary vertex has its barrier, however many tetrahedra surround it: each centre of a
// fan box is in 48 tetrahedra with 49 neighbours, its solid angles summing to 2 pi (flat, inside
// a face).
TEST(PolycubeTermsSizes, StarsOfManyTetrahedraHaveTheirBarriers) {
    const PreparedPolycube p =
        prepare_polycube(testing::fan_box(12), "fan box", PolycubeLabelInput{});
    const auto a_form = solid_angle_sum_elements(p);
    const auto vertex_form = solid_angle_sum_vertex_elements(p);
    ASSERT_EQ(a_form.items.size(), Index(p.stars.size()));
    const std::vector<double> sums = solid_angle_sums(p.stars, p.mesh.vertices);
    int centres = 0;
    for (std::size_t s = 0; s < p.stars.size(); ++s) {
        if (p.stars[s].vertex > 1) continue;
        ++centres;
        const Index e = Index(s);
        const int tets = int(p.stars[s].tets.size());
        EXPECT_GT(tets, 14);
        EXPECT_GT(vertex_form.items.arity(e), 40);
        EXPECT_NEAR(sums[s], 2 * M_PI, 1e-9);
        EXPECT_NEAR(a_form.energy.value(e, repeated(Mat<3>::Identity(), tets)), 1.0 / (2 * M_PI),
                    1e-12);
        EXPECT_NEAR(vertex_form.energy.value(e, gathered(p.mesh.vertices, vertex_form.items[e])),
                    1.0 / (2 * M_PI), 1e-12);
    }
    EXPECT_EQ(centres, 2);
}

}  // namespace
}  // namespace sa
