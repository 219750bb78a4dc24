#include "geometry/maps/arap_local_step.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "geometry/maps/vertex_recovery.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/quality/map_quality.h"
#include "tests/fixtures/random_matrices.h"

namespace sa {
namespace {

Mat<3> some_rotation() {
    return Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
}

// Kuhn tetrahedra are not regular: their edge covariances C_i are not multiples of the identity.
TEST(ArapLocalStep, RecoversTheRotationAndScaleOfASimilarity) {
    const SimplicialMesh mesh = grid_tetrahedra(2, 2, 2);
    const RestFrames<3> frames = rest_frames<3>(mesh);
    const double scale = 1.7;
    const std::vector<Mat<3>> A(mesh.num_simplices(), scale * some_rotation());
    std::vector<Mat<3>> M;
    const double rigid = fit_rigid_parts<3>(frames, A, false, M);
    double expected = 0.0;
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        EXPECT_LT((M[s] - some_rotation()).norm(), 1e-12);
        expected += (scale - 1.0) * (scale - 1.0) * 4.0 *
                    (frames.corners[s] * frames.corners[s].transpose()).trace();
    }
    EXPECT_NEAR(rigid, expected, 1e-12 * expected);
    EXPECT_NEAR(fit_rigid_parts<3>(frames, A, true, M), 0.0, 1e-20);
    for (const Mat<3>& m : M) EXPECT_LT((m - scale * some_rotation()).norm(), 1e-12);
}

// The edge energy of the fitted rotation is never above that of the closest rotation to A_i.
TEST(ArapLocalStep, IsTheMinimizerOfTheEdgeEnergy) {
    const SimplicialMesh mesh = grid_tetrahedra(2, 2, 2);
    const RestFrames<3> frames = rest_frames<3>(mesh);
    std::vector<Mat<3>> A(mesh.num_simplices());
    for (Mat<3>& a : A) a = Mat<3>::Identity() + 0.8 * Mat<3>::Random();
    std::vector<Mat<3>> M, projected = A;
    fit_rigid_parts<3>(frames, A, false, M);
    for (Mat<3>& p : projected) p = closest_rotation_by_svd<3>(p);
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        const Mat<3> C = 4.0 * frames.corners[s] * frames.corners[s].transpose();
        auto edge_energy = [&](const Mat<3>& R) {
            return ((R - A[s]) * C * (R - A[s]).transpose()).trace();
        };
        EXPECT_LE(edge_energy(M[s]), edge_energy(projected[s]) + 1e-12);
        EXPECT_NEAR(M[s].determinant(), 1.0, 1e-12);
    }
}

// Local/global iterations with the top of a bar turned by 120 degrees: Q never increases and
// the twist spreads through the bar.
TEST(ArapLocalStep, LocalGlobalIterationsAreMonotone) {
    SimplicialMesh mesh = grid_tetrahedra(2, 2, 8);
    const RestFrames<3> frames = rest_frames<3>(mesh);
    const double top = mesh.vertices.col(2).maxCoeff();
    std::vector<unsigned char> fixed(mesh.num_vertices(), 0);
    Eigen::MatrixXd x = mesh.vertices;
    const Mat<3> twist =
        Eigen::AngleAxisd(2.0 * M_PI / 3.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        const double z = mesh.vertices(v, 2);
        if (z == 0.0) fixed[v] = 1;
        if (z == top) {
            fixed[v] = 1;
            x.row(v) = (twist * mesh.vertices.row(v).transpose()).transpose();
        }
    }
    const VertexRecovery<3> recovery(mesh, frames, fixed);
    std::vector<Mat<3>> M;
    double previous = fit_rigid_parts<3>(frames, linear_parts<3>(mesh, frames, x), false, M);
    const double first = previous;
    for (int k = 0; k < 30; ++k) {
        x = recovery.recover(M, x);
        const double energy =
            fit_rigid_parts<3>(frames, linear_parts<3>(mesh, frames, x), false, M);
        EXPECT_LE(energy, previous * (1.0 + 1e-12)) << "iteration " << k;
        previous = energy;
    }
    EXPECT_LT(previous, 0.1 * first);
}

}  // namespace
}  // namespace sa
