// Loops generating a surface's first homology (geometry/mesh/homology_loops.h): none on a disk or a
// sphere, one around an annulus' hole, two independent ones on a torus and on a ring's boundary.
#include "geometry/mesh/homology_loops.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <set>

#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/tet_boundary.h"
#include "tests/fixtures/voxel_meshes.h"

namespace sa {
namespace {

std::vector<std::array<Index, 3>> rows(const Eigen::MatrixXi& triangles) {
    std::vector<std::array<Index, 3>> out;
    for (Index t = 0; t < triangles.rows(); ++t)
        out.push_back({triangles(t, 0), triangles(t, 1), triangles(t, 2)});
    return out;
}

// Every step of every loop, the closing one included, is an edge of a triangle.
void expect_closed_edge_paths(const std::vector<std::vector<Index>>& loops,
                              const std::vector<std::array<Index, 3>>& triangles) {
    std::set<std::pair<Index, Index>> edges;
    for (const auto& t : triangles) {
        for (int k = 0; k < 3; ++k) {
            edges.emplace(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
        }
    }
    for (const auto& loop : loops) {
        ASSERT_GE(loop.size(), 3u);
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const Index a = loop[k], b = loop[(k + 1) % loop.size()];
            EXPECT_TRUE(edges.count({std::min(a, b), std::max(a, b)})) << a << " " << b;
        }
    }
}

// How many times the loop turns around a circle, from an angle per vertex.
int winding(const std::vector<Index>& loop, const std::function<double(Index)>& angle) {
    double total = 0.0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
        double step = angle(loop[(k + 1) % loop.size()]) - angle(loop[k]);
        step = std::remainder(step, 2.0 * M_PI);
        total += step;
    }
    return static_cast<int>(std::lround(total / (2.0 * M_PI)));
}

TEST(HomologyLoops, NoneOnADiskOrASphere) {
    const SimplicialMesh disk = grid_triangles(6, 5);
    EXPECT_TRUE(homology_loops(disk.num_vertices(), rows(disk.simplices)).empty());
    const SimplicialMesh sphere = sphere_triangles(4);
    EXPECT_TRUE(homology_loops(sphere.num_vertices(), rows(sphere.simplices)).empty());
}

TEST(HomologyLoops, OneAroundTheHoleOfAnAnnulus) {
    // A 6 x 6 grid without its middle 2 x 2 cells.
    const SimplicialMesh grid = grid_triangles(6, 6);
    std::vector<std::array<Index, 3>> triangles;
    for (Index t = 0; t < grid.num_simplices(); ++t) {
        const Index cell = t / 2, i = cell % 6, j = cell / 6;
        if ((i == 2 || i == 3) && (j == 2 || j == 3)) continue;
        triangles.push_back({grid.simplices(t, 0), grid.simplices(t, 1), grid.simplices(t, 2)});
    }
    const auto loops = homology_loops(grid.num_vertices(), triangles);
    ASSERT_EQ(loops.size(), 1u);
    expect_closed_edge_paths(loops, triangles);
    const auto around_middle = [&](Index v) {
        return std::atan2(grid.vertices(v, 1) - 0.5, grid.vertices(v, 0) - 0.5);
    };
    EXPECT_EQ(std::abs(winding(loops[0], around_middle)), 1);
}

TEST(HomologyLoops, TwoIndependentOnATorus) {
    const double R = 1.0, r = 0.4;
    const SimplicialMesh torus = torus_triangles(12, 8, R, r);
    const auto triangles = rows(torus.simplices);
    const auto loops = homology_loops(torus.num_vertices(), triangles);
    ASSERT_EQ(loops.size(), 2u);
    expect_closed_edge_paths(loops, triangles);
    const auto& x = torus.vertices;
    const auto around_axis = [&](Index v) { return std::atan2(x(v, 1), x(v, 0)); };
    const auto around_tube = [&](Index v) {
        return std::atan2(x(v, 2), std::hypot(x(v, 0), x(v, 1)) - R);
    };
    // The loops' windings around the two circles are independent: they generate H1 = Z^2.
    const int a = winding(loops[0], around_axis), b = winding(loops[0], around_tube);
    const int c = winding(loops[1], around_axis), d = winding(loops[1], around_tube);
    EXPECT_NE(a * d - b * c, 0) << a << " " << b << " " << c << " " << d;
}

TEST(HomologyLoops, TheBoundaryOfASolidRingCarriesItsHandle) {
    const SimplicialMesh ring = testing::voxel_tetrahedra(testing::ring(2));
    const TetBoundary boundary = tet_boundary(ring, mesh_topology(ring, "generated"));
    const auto triangles = rows(boundary.triangles);
    const auto loops = homology_loops(ring.num_vertices(), triangles);
    ASSERT_EQ(loops.size(), 2u);  // the handle's two circles; one bounds a disk in the solid
    expect_closed_edge_paths(loops, triangles);
    const auto around_hole = [&](Index v) {
        return std::atan2(ring.vertices(v, 1) - 1.5, ring.vertices(v, 0) - 1.5);
    };
    EXPECT_EQ(std::abs(winding(loops[0], around_hole)) + std::abs(winding(loops[1], around_hole)),
              1);
}

}  // namespace
}  // namespace sa
