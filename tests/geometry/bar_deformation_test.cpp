#include "tests/fixtures/bar_deformation.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>

#include "geometry/mesh/rest_frames.h"
#include "optim/errors.h"

namespace sa {
namespace {

struct Slabs {
    std::vector<std::size_t> left, right;  // positions in handles / targets
};

Slabs slabs(const BarDeformation& bar, double length) {
    Slabs s;
    for (std::size_t k = 0; k < bar.handles.size(); ++k) {
        (bar.mesh.vertices(bar.handles[k], 0) < 0.5 * length ? s.left : s.right).push_back(k);
    }
    return s;
}

// The slab's targets are a rigid motion R p + t of its rest vertices: the affine least-squares
// fit is a rotation and fits every point.
void expect_rigid(const BarDeformation& bar, const std::vector<std::size_t>& slab,
                  Eigen::Matrix3d& R, Eigen::Vector3d& t) {
    Eigen::MatrixXd P(slab.size(), 4), Q(slab.size(), 3);
    for (std::size_t i = 0; i < slab.size(); ++i) {
        P.row(i) << bar.mesh.vertices.row(bar.handles[slab[i]]), 1.0;
        Q.row(i) = bar.targets.row(slab[i]);
    }
    const Eigen::MatrixXd X = P.colPivHouseholderQr().solve(Q);  // 4 x 3
    R = X.topRows(3).transpose();
    t = X.row(3).transpose();
    EXPECT_TRUE((R.transpose() * R).isIdentity(1e-12));
    EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
    EXPECT_LE((P * X - Q).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(BarDeformation, AboutEightThousandTetrahedraFiveToOneToOne) {
    const BarDeformation bar = bar_deformation(BarPose::kBend);
    EXPECT_EQ(bar.name, "bar-bend");
    EXPECT_EQ(bar.mesh.num_simplices(), 7776);
    EXPECT_EQ(bar.mesh.num_vertices(), 37 * 7 * 7);
    const Eigen::RowVector3d size =
        bar.mesh.vertices.colwise().maxCoeff() - bar.mesh.vertices.colwise().minCoeff();
    EXPECT_NEAR(size[0], 5.0, 1e-12);
    EXPECT_NEAR(size[1], 1.0, 1e-12);
    EXPECT_NEAR(size[2], 1.0, 1e-12);
    const RestFrames<3> frames = rest_frames<3>(bar.mesh);
    for (Index s = 0; s < bar.mesh.num_simplices(); ++s) {
        EXPECT_GT(frames.edge_inverse[s].determinant(), 0.0);
    }
    // Two vertex layers at each end (x spacing 5/36, slab 0.25).
    EXPECT_EQ(bar.handles.size(), std::size_t(4 * 49));
    EXPECT_EQ(bar.targets.rows(), 4 * 49);
}

TEST(BarDeformation, LeftSlabStaysRightSlabMovesRigidly) {
    for (BarPose pose :
         {BarPose::kBend, BarPose::kTwist, BarPose::kTranslate, BarPose::kBendTwist}) {
        SCOPED_TRACE(to_string(pose));
        const BarDeformation bar = bar_deformation(pose);
        const Slabs s = slabs(bar, 5.0);
        ASSERT_EQ(s.left.size(), s.right.size());
        for (std::size_t k : s.left)
            EXPECT_EQ(bar.targets.row(k), bar.mesh.vertices.row(bar.handles[k]));
        Eigen::Matrix3d R;
        Eigen::Vector3d t;
        expect_rigid(bar, s.right, R, t);
        const Eigen::Vector3d end = R * Eigen::Vector3d(5.0, 0.5, 0.5) + t;
        switch (pose) {
            case BarPose::kBend:
                // The bar's axis turns to +y; the end lies on the quarter circle of radius 10/pi.
                EXPECT_TRUE((R * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY()));
                EXPECT_TRUE(end.isApprox(Eigen::Vector3d(10 / M_PI, 0.5 + 10 / M_PI, 0.5)));
                break;
            case BarPose::kTwist:
                EXPECT_TRUE(R.isApprox(Eigen::Vector3d(1, -1, -1).asDiagonal().toDenseMatrix()));
                EXPECT_TRUE(end.isApprox(Eigen::Vector3d(5.0, 0.5, 0.5)));
                break;
            case BarPose::kTranslate:
                EXPECT_TRUE(R.isIdentity(1e-12));
                EXPECT_TRUE(t.isApprox(Eigen::Vector3d(0, 1, 0)));
                break;
            case BarPose::kBendTwist:
                // The bend's end, the cross-section also turned half a turn about the axis (+y).
                EXPECT_TRUE((R * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY()));
                EXPECT_TRUE((R * Eigen::Vector3d::UnitZ()).isApprox(-Eigen::Vector3d::UnitZ()));
                EXPECT_TRUE(end.isApprox(Eigen::Vector3d(10 / M_PI, 0.5 + 10 / M_PI, 0.5)));
                break;
        }
    }
}

TEST(BarDeformation, OptionsAndNames) {
    BarDeformationOptions small;
    small.length_cells = 10;
    small.cross_cells = 2;
    small.bend_degrees = 45.0;
    const BarDeformation bar = bar_deformation(BarPose::kBend, small);
    EXPECT_EQ(bar.mesh.num_simplices(), 10 * 2 * 2 * 6);
    for (BarPose pose : {BarPose::kBend, BarPose::kTwist, BarPose::kTranslate, BarPose::kBendTwist})
        EXPECT_EQ(parse_bar_pose(to_string(pose)), pose);
    EXPECT_THROW(parse_bar_pose("stretch"), InvalidArgumentError);
    BarDeformationOptions bad;
    bad.slab = 0.6;
    EXPECT_THROW(bar_deformation(BarPose::kTwist, bad), InvalidArgumentError);
    bad = {};
    bad.cross_cells = 0;
    EXPECT_THROW(bar_deformation(BarPose::kTwist, bad), InvalidArgumentError);
}

}  // namespace
}  // namespace sa
