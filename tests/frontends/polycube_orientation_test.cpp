#include "frontends/polycube/polycube_orientation.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "geometry/mesh/mesh_topology.h"
#include "tests/fixtures/polycube_fixtures.h"

namespace sa {
namespace {

using testing::l_shape;
using testing::voxel_tetrahedra;

PolycubeOrientation orientation_of(const SimplicialMesh& mesh) {
    const MeshTopology topology = mesh_topology(mesh, "test");
    return polycube_orientation(tet_boundary(mesh, topology), mesh.vertices);
}

SimplicialMesh turned(SimplicialMesh mesh, const Eigen::Matrix3d& r) {
    mesh.vertices = mesh.vertices * r.transpose();
    return mesh;
}

TEST(PolycubeOrientation, AnAxisAlignedShapeKeepsItsOrientation) {
    const PolycubeOrientation o = orientation_of(voxel_tetrahedra(l_shape(), 2));
    EXPECT_EQ(o.rotation, Eigen::Matrix3d::Identity());
    EXPECT_EQ(o.angle_degrees, 0.0);
    EXPECT_NEAR(o.energy_identity, 1.0, 1e-12);
    EXPECT_EQ(o.energy, o.energy_identity);
}

// Turned by 40 degrees about an oblique axis, the L-shape's faces point between the axes; the
// search turns them back onto the axes (up to one of the cube's rotations, which E cannot see).
TEST(PolycubeOrientation, ATurnedShapeIsTurnedBackOntoTheAxes) {
    const Eigen::Matrix3d r =
        Eigen::AngleAxisd(40.0 * M_PI / 180.0, Eigen::Vector3d(1.0, 2.0, 0.5).normalized())
            .toRotationMatrix();
    const SimplicialMesh mesh = turned(voxel_tetrahedra(l_shape(), 2), r);
    const PolycubeOrientation o = orientation_of(mesh);
    EXPECT_GT(o.energy_identity, 1.2);
    EXPECT_NEAR(o.energy, 1.0, 1e-6);
    EXPECT_NEAR(o.angle_degrees, 40.0, 1e-3);
    EXPECT_TRUE(o.rotation.isUnitary(1e-12));
    EXPECT_NEAR(o.rotation.determinant(), 1.0, 1e-12);
    // Every turned-back face normal is an axis.
    const MeshTopology topology = mesh_topology(mesh, "test");
    const Eigen::MatrixXd areas =
        boundary_area_vectors(tet_boundary(mesh, topology), mesh.vertices * o.rotation.transpose());
    for (Index b = 0; b < areas.rows(); ++b) {
        const Eigen::Vector3d a = areas.row(b).transpose();
        EXPECT_NEAR(a.cwiseAbs().maxCoeff(), a.norm(), 1e-6 * a.norm()) << "triangle " << b;
    }
}

TEST(PolycubeOrientation, L1AlignmentOfAFaceBetweenTwoAxes) {
    Eigen::MatrixXd areas(2, 3);
    areas << 1.0, 1.0, 0.0, 0.0, 0.0, -2.0;
    const double half = (std::sqrt(2.0) * std::sqrt(2.0) + 2.0) / (std::sqrt(2.0) + 2.0);
    EXPECT_NEAR(l1_alignment(areas, Eigen::Matrix3d::Identity()), half, 1e-15);
}

}  // namespace
}  // namespace sa
