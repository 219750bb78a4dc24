#include "frontends/seamless/cut_graph.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "frontends/seamless/cross_field.h"
#include "geometry/mesh/boundary_loops.h"
#include "geometry/mesh/mesh_generators.h"

namespace sa {
namespace {

// The cut mesh is a disk (one boundary loop, Euler characteristic 1) with every `through` vertex on
// its boundary.
void expect_disk_through(const SimplicialMesh& mesh, const std::vector<Index>& through) {
    const MeshTopology t = mesh_topology(mesh, "surface");
    const CutMesh cut = cut_along(mesh, t, cut_graph(mesh, t, through));
    const MeshTopology ct = mesh_topology(cut.mesh, "cut");
    EXPECT_NO_THROW(require_disk(cut.mesh, ct, "cut"));
    for (Index v : through) {
        bool on_boundary = false;
        for (std::size_t c = 0; c < cut.original_vertex.size(); ++c) {
            on_boundary |= cut.original_vertex[c] == v && ct.boundary_vertex[c];
        }
        EXPECT_TRUE(on_boundary) << "vertex " << v;
    }
}

TEST(CutGraph, OpensClosedSurfacesIntoDisksThroughTheSingularities) {
    const SimplicialMesh torus = torus_triangles(20, 10);
    expect_disk_through(torus, {});  // genus 1: two loops, no singularity needed
    const SimplicialMesh sphere = sphere_triangles(6);
    const MeshTopology t = mesh_topology(sphere, "sphere");
    std::vector<Index> singular;
    for (const Singularity& s :
         cross_field_singularities(sphere, t, smoothest_cross_field(sphere, t)))
        singular.push_back(s.vertex);
    ASSERT_GE(singular.size(), 8u);
    expect_disk_through(sphere, singular);
}

TEST(CutGraph, ADiskIsCutFromItsSingularityToTheBoundary) {
    const SimplicialMesh square = grid_triangles(10, 10);
    const MeshTopology t = mesh_topology(square, "square");
    const std::vector<unsigned char> none = cut_graph(square, t, {});
    EXPECT_EQ(std::count(none.begin(), none.end(), 1), 0);  // a disk needs no cut
    expect_disk_through(square, {5 * 11 + 5});
}

TEST(CrossFieldMatchings, CountQuarterTurnsAcrossEdges) {
    const SimplicialMesh square = grid_triangles(4, 4);
    const MeshTopology t = mesh_topology(square, "square");
    Eigen::MatrixXd d = Eigen::MatrixXd::Zero(square.num_simplices(), 3);
    d.col(0).setOnes();
    for (int k : cross_field_matchings(square, t, d)) EXPECT_EQ(k, 0);
    d.row(9) << 0.0, 1.0, 0.0;  // the same cross, another representative: a quarter turn
    const std::vector<int> m = cross_field_matchings(square, t, d);
    for (std::size_t i = 0; i < m.size(); ++i) {
        const auto& s = t.interior_facets[i].simplex;
        const int expected = s[1] == 9 ? 1 : s[0] == 9 ? 3 : 0;
        EXPECT_EQ(m[i], expected) << "facet " << i;
    }
    EXPECT_TRUE(cross_field_singularities(square, t, d).empty());
}

}  // namespace
}  // namespace sa
