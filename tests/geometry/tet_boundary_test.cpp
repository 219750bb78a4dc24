// The boundary of a tetrahedral mesh (geometry/mesh/tet_boundary.h): the loops a solid's handles
// make, counted from its boundary surface.
#include "geometry/mesh/tet_boundary.h"

#include <gtest/gtest.h>

#include "geometry/mesh/mesh_topology.h"
#include "optim/errors.h"
#include "tests/fixtures/voxel_meshes.h"

namespace sa {
namespace {

Index loops_of(const std::vector<testing::Cell>& cells) {
    const SimplicialMesh mesh = testing::voxel_tetrahedra(cells);
    return independent_loops(tet_boundary(mesh, mesh_topology(mesh, "generated")));
}

TEST(IndependentLoops, OnePerHandleNoneForABallOrACavity) {
    EXPECT_EQ(loops_of({{0, 0, 0}}), 0);
    EXPECT_EQ(loops_of(testing::l_shape()), 0);
    EXPECT_EQ(loops_of(testing::ring()), 1);
    EXPECT_EQ(loops_of(testing::ring(2)), 1);
    // Two rings side by side, sharing a wall: a handlebody of genus 2.
    std::vector<testing::Cell> two = testing::ring();
    for (int x = 3; x < 5; ++x)
        for (int y = 0; y < 3; ++y)
            if (x != 3 || y != 1) two.push_back({x, y, 0});
    EXPECT_EQ(loops_of(two), 2);
    // A 3 x 3 x 3 block without its middle cube: two boundary components, no loop.
    std::vector<testing::Cell> hollow;
    for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y)
            for (int z = 0; z < 3; ++z)
                if (x != 1 || y != 1 || z != 1) hollow.push_back({x, y, z});
    EXPECT_EQ(loops_of(hollow), 0);
    // Two separate rings: one loop each.
    std::vector<testing::Cell> apart = testing::ring();
    for (const testing::Cell& c : testing::ring()) apart.push_back({c[0] + 5, c[1], c[2]});
    EXPECT_EQ(loops_of(apart), 2);
}

TEST(IndependentLoops, ABoundaryThatIsNotClosedIsRefused) {
    // Two cubes that share only an edge: four boundary triangles on that edge.
    const SimplicialMesh mesh = testing::voxel_tetrahedra({{0, 0, 0}, {1, 1, 0}});
    EXPECT_THROW(independent_loops(tet_boundary(mesh, mesh_topology(mesh, "generated"))),
                 InvalidArgumentError);
}

}  // namespace
}  // namespace sa
