#include "frontends/polycube/polycube_terms.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>

#include "../geometry/polycube_fixtures.h"
#include "frontends/polycube/boundary_angle_sums.h"
#include "geometry/polycube_planes.h"

namespace sa {
namespace {

template <int N>
Vec<N> repeated(const Mat<3>& A) {
    Vec<N> x;
    for (int k = 0; k < N / 9; ++k)
        x.template segment<9>(9 * k) = Eigen::Map<const Vec<9>>(A.data());
    return x;
}

template <int N>
Vec<N> gathered(const Eigen::MatrixXd& positions, const std::array<Index, N / 3>& vertices) {
    Vec<N> x;
    for (int i = 0; i < N / 3; ++i)
        x.template segment<3>(3 * i) = positions.row(vertices[i]).transpose();
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
        EXPECT_LT(energy.value(e, repeated<9>(Mat<3>::Identity())), 1e-30);
        EXPECT_GT(energy.value(e, repeated<9>(turned)), 1e-4);
        EXPECT_LT(vertex_energy.value(e, gathered<9>(p.mesh.vertices, v.vertices[e])), 1e-30);
        Eigen::MatrixXd rotated = p.mesh.vertices * turned.transpose();
        EXPECT_GT(vertex_energy.value(e, gathered<9>(rotated, v.vertices[e])), 1e-4);
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
    std::size_t a_elements = 0, v_elements = 0;
    for_each_dihedral_term(
        p,
        [&](auto energy, auto tets) {
            constexpr int K = decltype(energy)::arity / 9;
            // Elements come in the order of the fans of K tetrahedra.
            std::size_t e = 0;
            for (const BoundaryEdgeFan& fan : p.fans) {
                if (int(fan.tets.size()) != K) continue;
                ASSERT_LT(e, tets.size());
                EXPECT_EQ(tets[e][0], fan.tets[0]);
                EXPECT_NEAR(energy.value(Index(e), repeated<9 * K>(Mat<3>::Identity())),
                            expected[fan.edge], 1e-12);
                ++e;
            }
            EXPECT_EQ(e, tets.size());
            a_elements += tets.size();
        },
        [&](auto energy, auto vertices) {
            constexpr int N = decltype(energy)::arity;
            for (std::size_t e = 0; e < vertices.size(); ++e) {
                const std::array<Index, 2> edge{vertices[e][0], vertices[e][1]};
                EXPECT_NEAR(energy.value(Index(e), gathered<N>(p.mesh.vertices, vertices[e])),
                            expected[edge], 1e-12);
            }
            v_elements += vertices.size();
        });
    EXPECT_EQ(a_elements, p.fans.size());
    EXPECT_EQ(v_elements, p.fans.size());

    const std::vector<double> vertex_sums = solid_angle_sums(p.stars, p.mesh.vertices);
    std::map<Index, double> expected_v;
    for (std::size_t s = 0; s < p.stars.size(); ++s) {
        expected_v[p.stars[s].vertex] = 1.0 / (4 * M_PI - vertex_sums[s]);
    }
    std::vector<Index> skipped;
    a_elements = v_elements = 0;
    for_each_solid_angle_term(
        p,
        [&](auto energy, auto tets) {
            constexpr int K = decltype(energy)::arity / 9;
            std::size_t e = 0;
            for (const BoundaryVertexStar& star : p.stars) {
                if (int(star.tets.size()) != K) continue;
                ASSERT_LT(e, tets.size());
                EXPECT_EQ(tets[e][0], star.tets[0]);
                EXPECT_NEAR(energy.value(Index(e), repeated<9 * K>(Mat<3>::Identity())),
                            expected_v[star.vertex], 1e-12);
                ++e;
            }
            EXPECT_EQ(e, tets.size());
            a_elements += tets.size();
        },
        [&](auto energy, auto vertices) {
            constexpr int N = decltype(energy)::arity;
            for (std::size_t e = 0; e < vertices.size(); ++e) {
                EXPECT_NEAR(energy.value(Index(e), gathered<N>(p.mesh.vertices, vertices[e])),
                            expected_v[vertices[e][0]], 1e-12);
            }
            v_elements += vertices.size();
        },
        &skipped);
    EXPECT_EQ(v_elements, p.stars.size());
    EXPECT_EQ(a_elements + skipped.size(), p.stars.size());
}

// A boundary vertex with more neighbours than the vertex form takes (kMaxAngleRing) is left out
// of both forms and named, not refused: the angle sums still measure it.
TEST(PolycubeTermsLimits, StarsBeyondTheFixedSizesAreLeftOutAndNamed) {
    const PreparedPolycube p =
        prepare_polycube(testing::fan_box(12), "fan box", PolycubeLabelInput{});
    std::vector<Index> large;
    for (const BoundaryVertexStar& star : p.stars) {
        if (star.ring.size() > std::size_t(kMaxAngleRing)) large.push_back(star.vertex);
    }
    ASSERT_EQ(large, (std::vector<Index>{0, 1}));  // the two centres
    std::vector<Index> skipped;
    std::size_t a_elements = 0, v_elements = 0;
    for_each_solid_angle_term(
        p, [&](auto, auto tets) { a_elements += tets.size(); },
        [&](auto, auto vertices) {
            for (const auto& ids : vertices) EXPECT_NE(ids[0], 0);
            v_elements += vertices.size();
        },
        &skipped);
    EXPECT_EQ(v_elements, p.stars.size() - 2);
    EXPECT_EQ(a_elements + skipped.size(), p.stars.size());
    EXPECT_NE(std::find(skipped.begin(), skipped.end(), 0), skipped.end());
    EXPECT_NE(std::find(skipped.begin(), skipped.end(), 1), skipped.end());
    const std::vector<double> sums = solid_angle_sums(p.stars, p.mesh.vertices);
    for (std::size_t s = 0; s < p.stars.size(); ++s) {
        if (p.stars[s].vertex <= 1) {
            EXPECT_NEAR(sums[s], 2 * M_PI, 1e-9);  // flat, inside a face
        }
    }
    skipped.clear();
    std::size_t fans = 0;
    for_each_dihedral_term(
        p, [&](auto, auto tets) { fans += tets.size(); }, [](auto, auto) {}, &skipped);
    EXPECT_EQ(fans + skipped.size(), p.fans.size());
}

}  // namespace
}  // namespace sa
