#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <cmath>

#include "geometry/maps/initial_maps.h"
#include "geometry/mesh/boundary_fans.h"
#include "geometry/mesh/boundary_loops.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/quality/map_quality.h"
#include "optim/errors.h"

namespace sa {
namespace {

// A bumpy disk: the unit square grid lifted by a smooth height field (a surface in space).
SimplicialMesh bumpy(int n) {
    SimplicialMesh mesh = grid_triangles(n, n);
    Eigen::MatrixXd lifted(mesh.num_vertices(), 3);
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        const double x = mesh.vertices(v, 0), y = mesh.vertices(v, 1);
        lifted.row(v) << x, y, 0.3 * std::sin(3.0 * x) * std::cos(2.0 * y);
    }
    mesh.vertices = lifted;
    return mesh;
}

MapQuality quality_of(const SimplicialMesh& mesh, const Eigen::MatrixXd& uv) {
    const RestFrames<2> frames = rest_frames<2>(mesh);
    return map_quality<2>(linear_parts<2>(mesh, frames, uv), frames.volume);
}

TEST(InitialMaps, TutteOntoACircleHasNoFoldovers) {
    const SimplicialMesh mesh = bumpy(20);
    const MeshTopology t = mesh_topology(mesh, "bumpy");
    for (TutteWeights w : {TutteWeights::kUniform, TutteWeights::kMeanValue}) {
        const Eigen::MatrixXd uv = tutte_embedding(mesh, t, w);
        const MapQuality q = quality_of(mesh, uv);
        EXPECT_EQ(q.inverted, 0);
        EXPECT_EQ(q.degenerate, 0);
        const std::vector<Index> loop = boundary_loops(mesh, t).front();
        for (Index v : loop) EXPECT_NEAR(uv.row(v).norm(), 1.0, 1e-12);
    }
}

TEST(InitialMaps, LscmReproducesAPlanarMeshUpToASimilarity) {
    SimplicialMesh mesh = grid_triangles(12, 9);
    mesh.vertices.col(0) *= 1.7;   // not a square
    mesh.vertices(40, 1) += 0.02;  // and not regular
    const MeshTopology t = mesh_topology(mesh, "grid");
    const Eigen::MatrixXd uv = lscm(mesh, t);
    // Fit uv = s R x + c (Procrustes) and check the residual.
    const Eigen::RowVector2d cx = mesh.vertices.colwise().mean(), cu = uv.colwise().mean();
    const Eigen::MatrixXd X = mesh.vertices.rowwise() - cx, U = uv.rowwise() - cu;
    const Eigen::JacobiSVD<Eigen::Matrix2d> svd(X.transpose() * U,
                                                Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix2d R = svd.matrixV() * svd.matrixU().transpose();
    const double s = svd.singularValues().sum() / X.squaredNorm();
    const double residual = (U - s * X * R.transpose()).cwiseAbs().maxCoeff();
    EXPECT_GT(R.determinant(), 0.0);  // no reflection
    EXPECT_LT(residual, 1e-9 * s);
    EXPECT_LT(quality_of(mesh, uv).conformal.max, 1.0 + 1e-9);
}

// The gradient of the LSCM energy sum_t area_t |r_t|^2 (r_1 = A00 - A11, r_2 = A10 + A01),
// assembled triangle by triangle, at uv: #V x 2.
Eigen::MatrixXd lscm_gradient(const SimplicialMesh& mesh, const Eigen::MatrixXd& uv) {
    const RestFrames<2> frames = rest_frames<2>(mesh);
    const std::vector<Mat<2>> A = linear_parts<2>(mesh, frames, uv);
    Eigen::MatrixXd gradient = Eigen::MatrixXd::Zero(mesh.num_vertices(), 2);
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        const Mat<2>& R = frames.edge_inverse[s];
        const Eigen::Vector2d g[3] = {-(R.row(0) + R.row(1)).transpose(), R.row(0).transpose(),
                                      R.row(1).transpose()};
        const double r1 = A[s](0, 0) - A[s](1, 1), r2 = A[s](1, 0) + A[s](0, 1);
        for (int k = 0; k < 3; ++k) {
            // dA00/du_k = g_k.x, dA01/du_k = g_k.y, dA10/dv_k = g_k.x, dA11/dv_k = g_k.y.
            const Index v = mesh.simplices(s, k);
            gradient(v, 0) += 2.0 * frames.volume[s] * (r1 * g[k].x() + r2 * g[k].y());
            gradient(v, 1) += 2.0 * frames.volume[s] * (-r1 * g[k].y() + r2 * g[k].x());
        }
    }
    return gradient;
}

TEST(InitialMaps, LscmMinimizesTheEnergyAssembledPerTriangle) {
    // A curved disk with a free boundary: the solution is stationary for the per-triangle energy
    // at every vertex but the two pins.
    const SimplicialMesh mesh = bumpy(14);
    const Eigen::MatrixXd uv = lscm(mesh, mesh_topology(mesh, "bumpy"));
    const Eigen::MatrixXd gradient = lscm_gradient(mesh, uv);
    const double scale = gradient.cwiseAbs().maxCoeff();
    ASSERT_GT(scale, 1e-6);  // the pins hold the map
    int stationary = 0;
    for (Index v = 0; v < mesh.num_vertices(); ++v)
        stationary += gradient.row(v).norm() < 1e-9 * scale;
    EXPECT_EQ(stationary, mesh.num_vertices() - 2);
    EXPECT_EQ(quality_of(mesh, uv).inverted, 0);

    // A planar disk listed clockwise: reproduced up to a similarity, orientation kept.
    SimplicialMesh clockwise = grid_triangles(9, 7);
    clockwise.vertices.col(1) += 0.2 * clockwise.vertices.col(0).array().square().matrix();
    clockwise.simplices.col(1).swap(clockwise.simplices.col(2));
    const Eigen::MatrixXd flat = lscm(clockwise, mesh_topology(clockwise, "clockwise"));
    const MapQuality q = quality_of(clockwise, flat);
    EXPECT_EQ(q.inverted, 0);
    EXPECT_LT(q.conformal.max, 1.0 + 1e-9);
}

TEST(InitialMaps, BoundaryAngleSumsOfAPlanarGrid) {
    const SimplicialMesh mesh = grid_triangles(5, 4);
    const MeshTopology t = mesh_topology(mesh, "grid");
    const std::vector<BoundaryFan> fans = boundary_fans(mesh, t);
    EXPECT_EQ(fans.size(), 2u * (5 + 4));
    int corners = 0;
    for (double theta : boundary_angle_sums(fans, mesh.vertices)) {
        EXPECT_TRUE(std::abs(theta - M_PI) < 1e-12 || std::abs(theta - M_PI / 2) < 1e-12) << theta;
        corners += std::abs(theta - M_PI / 2) < 1e-12;
    }
    EXPECT_EQ(corners, 4);
}

TEST(InitialMaps, OnlyDisksAreAccepted) {
    // Closed: the surface of a tetrahedron.
    SimplicialMesh closed;
    closed.vertices.resize(4, 3);
    closed.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
    closed.simplices.resize(4, 3);
    closed.simplices << 0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2;
    EXPECT_THROW(require_disk(closed, mesh_topology(closed, "closed.off"), "closed.off"),
                 InputError);
    try {
        require_disk(closed, mesh_topology(closed, "closed.off"), "closed.off");
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("closed.off: the mesh is closed"), std::string::npos)
            << e.what();
    }
    // Two boundary loops: a square with a hole (remove the middle cell's two triangles).
    SimplicialMesh annulus = grid_triangles(3, 3);
    Eigen::MatrixXi kept(annulus.num_simplices() - 2, 3);
    for (Index f = 0, k = 0; f < annulus.num_simplices(); ++f) {
        if (f != 8 && f != 9) kept.row(k++) = annulus.simplices.row(f);
    }
    annulus.simplices = kept;
    try {
        require_disk(annulus, mesh_topology(annulus, "annulus.obj"), "annulus.obj");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("annulus.obj: the mesh has 2 boundary loops"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_NO_THROW(require_disk(bumpy(3), mesh_topology(bumpy(3), "bumpy"), "bumpy"));
}

}  // namespace
}  // namespace sa
