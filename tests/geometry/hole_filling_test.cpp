#include "geometry/mesh/hole_filling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "geometry/maps/initial_maps.h"
#include "geometry/mesh/boundary_loops.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/rest_frames.h"
#include "geometry/quality/map_quality.h"
#include "optim/errors.h"

namespace sa {
namespace {

/// `mesh` without the triangles whose centroid is within `radius` of one of `centers`.
SimplicialMesh with_holes(const SimplicialMesh& mesh,
                          const std::vector<Eigen::RowVector3d>& centers, double radius) {
    std::vector<Index> kept;
    for (Index f = 0; f < mesh.num_simplices(); ++f) {
        Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
        for (int k = 0; k < 3; ++k) centroid += mesh.vertices.row(mesh.simplices(f, k)) / 3.0;
        bool far = true;
        for (const Eigen::RowVector3d& c : centers) far = far && (centroid - c).norm() > radius;
        if (far) kept.push_back(f);
    }
    // Only the vertices the kept triangles use, in their order.
    std::vector<Index> index(mesh.num_vertices(), -1);
    for (Index f : kept)
        for (int k = 0; k < 3; ++k) index[mesh.simplices(f, k)] = 0;
    Index used = 0;
    for (Index& i : index)
        if (i == 0) i = used++;
    SimplicialMesh holed;
    holed.vertices.resize(used, mesh.vertices.cols());
    for (Index v = 0; v < mesh.num_vertices(); ++v)
        if (index[v] >= 0) holed.vertices.row(index[v]) = mesh.vertices.row(v);
    holed.simplices.resize(Index(kept.size()), 3);
    for (std::size_t k = 0; k < kept.size(); ++k)
        for (int c = 0; c < 3; ++c) holed.simplices(k, c) = int(index[mesh.simplices(kept[k], c)]);
    return holed;
}

std::string error_of(const SimplicialMesh& mesh) {
    try {
        require_planar_surface(mesh, mesh_topology(mesh, "m.off"), "m.off");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(HoleFilling, ASphereWithThreeHolesGetsAValidTutteStart) {
    // Three holes around the equator and one at the south pole: the longest loop stays outer.
    const SimplicialMesh holed =
        with_holes(sphere_triangles(12),
                   {Eigen::RowVector3d(1, 0, 0), Eigen::RowVector3d(0, 1, 0),
                    Eigen::RowVector3d(-1, 0, 0), Eigen::RowVector3d(0, 0, -1)},
                   0.35);
    const MeshTopology topology = mesh_topology(holed, "holed");
    ASSERT_EQ(require_planar_surface(holed, topology, "holed"), 4);
    const FilledHoles filled = fill_inner_holes(holed, topology);
    EXPECT_EQ(filled.holes, 3);
    EXPECT_EQ(filled.mesh.num_vertices(), holed.num_vertices() + 3);
    EXPECT_TRUE(filled.mesh.vertices.topRows(holed.num_vertices()) == holed.vertices);
    EXPECT_TRUE(filled.mesh.simplices.topRows(holed.num_simplices()) == holed.simplices);
    const MeshTopology disk_topology = mesh_topology(filled.mesh, "filled");  // oriented alike
    EXPECT_NO_THROW(require_disk(filled.mesh, disk_topology, "filled"));
    for (TutteWeights weights : {TutteWeights::kMeanValue, TutteWeights::kUniform}) {
        const Eigen::MatrixXd uv =
            tutte_embedding(filled.mesh, disk_topology, weights).topRows(holed.num_vertices());
        const RestFrames<2> frames = rest_frames<2>(holed);
        const MapQuality q = map_quality<2>(linear_parts<2>(holed, frames, uv), frames.volume);
        EXPECT_EQ(q.inverted, 0);
        EXPECT_EQ(q.degenerate, 0);
    }
}

TEST(HoleFilling, SurfacesThatCannotLieInThePlaneAreNamed) {
    EXPECT_NE(error_of(sphere_triangles(4)).find("m.off: the mesh is closed"), std::string::npos);
    // A torus with a hole: one loop, genus 1.
    const SimplicialMesh torus = torus_triangles(16, 8);
    const Eigen::RowVector3d on_torus = torus.vertices.row(0);
    EXPECT_NE(error_of(with_holes(torus, {on_torus}, 0.5)).find("(genus 1)"), std::string::npos)
        << error_of(with_holes(torus, {on_torus}, 0.5));
    // Two disks side by side.
    SimplicialMesh two = grid_triangles(2, 2);
    const Index nv = two.num_vertices();
    two.vertices.conservativeResize(2 * nv, 2);
    two.vertices.bottomRows(nv) = two.vertices.topRows(nv).array() + 5.0;
    two.simplices.conservativeResize(2 * two.simplices.rows(), 3);
    two.simplices.bottomRows(two.simplices.rows() / 2) =
        two.simplices.topRows(two.simplices.rows() / 2).array() + int(nv);
    EXPECT_NE(error_of(two).find("2 connected parts"), std::string::npos) << error_of(two);
}

}  // namespace
}  // namespace sa
