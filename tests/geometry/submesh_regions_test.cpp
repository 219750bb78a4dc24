#include <gtest/gtest.h>

#include <functional>

#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/submesh.h"

namespace sa {
namespace {

/// The simplices whose centroid passes `keep`, sorted.
std::vector<Index> select(const SimplicialMesh& mesh,
                          const std::function<bool(const Eigen::RowVectorXd&)>& keep) {
    std::vector<Index> out;
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        Eigen::RowVectorXd c = Eigen::RowVectorXd::Zero(mesh.vertices.cols());
        for (int k = 0; k < mesh.simplices.cols(); ++k)
            c += mesh.vertices.row(mesh.simplices(s, k));
        if (keep(c / double(mesh.simplices.cols()))) out.push_back(s);
    }
    return out;
}

bool in_box(const Eigen::RowVectorXd& c, double lo, double hi) {
    return (c.array() > lo).all() && (c.array() < hi).all();
}

TEST(FillEnclosed, AnAnnulusGetsItsHoleAndNothingOutside) {
    const SimplicialMesh mesh = grid_triangles(12, 12);
    const MeshTopology topology = mesh_topology(mesh, "grid");
    const auto annulus = select(mesh, [](const Eigen::RowVectorXd& c) {
        return in_box(c, 0.2, 0.8) && !in_box(c, 0.4, 0.6);
    });
    const auto expected =
        select(mesh, [](const Eigen::RowVectorXd& c) { return in_box(c, 0.2, 0.8); });
    ASSERT_LT(annulus.size(), expected.size());
    EXPECT_EQ(fill_enclosed(topology, annulus), expected);
}

TEST(FillEnclosed, RegionsWithoutHolesAreUnchanged) {
    const SimplicialMesh mesh = grid_triangles(12, 12);
    const MeshTopology topology = mesh_topology(mesh, "grid");
    // A strip from one side of the grid to the other splits the rest in two, both on the boundary.
    const auto strip =
        select(mesh, [](const Eigen::RowVectorXd& c) { return c[0] > 0.4 && c[0] < 0.6; });
    EXPECT_EQ(fill_enclosed(topology, strip), strip);
    const auto disk = select(mesh, [](const Eigen::RowVectorXd& c) { return in_box(c, 0.3, 0.7); });
    EXPECT_EQ(fill_enclosed(topology, disk), disk);
    EXPECT_TRUE(fill_enclosed(topology, {}).empty());
}

TEST(FillEnclosed, OnAClosedSurfaceTheLargestRestIsOutside) {
    const SimplicialMesh mesh = sphere_triangles(3);
    const MeshTopology topology = mesh_topology(mesh, "sphere");
    ASSERT_TRUE(topology.boundary_facets.empty());
    // A band around the equator leaves two caps; the band near the north pole encloses the
    // small cap, which is filled, and keeps the large one outside.
    const auto band = select(mesh, [](const Eigen::RowVectorXd& c) {
        const double z = c[2] / c.norm();
        return z > 0.5 && z < 0.8;
    });
    const auto expected =
        select(mesh, [](const Eigen::RowVectorXd& c) { return c[2] / c.norm() > 0.5; });
    ASSERT_LT(band.size(), expected.size());
    EXPECT_EQ(fill_enclosed(topology, band), expected);
}

TEST(FillEnclosed, ACavityInATetrahedralMeshIsFilled) {
    const SimplicialMesh mesh = grid_tetrahedra(6, 6, 6);
    const MeshTopology topology = mesh_topology(mesh, "grid");
    const auto shell = select(mesh, [](const Eigen::RowVectorXd& c) {
        return in_box(c, 0.15, 0.85) && !in_box(c, 0.35, 0.65);
    });
    const auto expected =
        select(mesh, [](const Eigen::RowVectorXd& c) { return in_box(c, 0.15, 0.85); });
    ASSERT_LT(shell.size(), expected.size());
    EXPECT_EQ(fill_enclosed(topology, shell), expected);
}

}  // namespace
}  // namespace sa
