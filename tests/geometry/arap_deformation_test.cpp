#include "geometry/maps/arap_deformation.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "geometry/mesh/mesh_generators.h"
#include "geometry/quality/map_quality.h"
#include "optim/errors.h"

namespace sa {
namespace {

// Vertices at the two ends of the box (x minimal or maximal): the handle slabs.
std::vector<Index> end_vertices(const SimplicialMesh& mesh) {
    const double lo = mesh.vertices.col(0).minCoeff(), hi = mesh.vertices.col(0).maxCoeff();
    std::vector<Index> handles;
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        const double x = mesh.vertices(v, 0);
        if (x <= lo + 1e-12 || x >= hi - 1e-12) handles.push_back(v);
    }
    return handles;
}

template <int D>
void check_rigid_motion(const SimplicialMesh& mesh, const Mat<D>& R, const Vec<D>& t,
                        const std::vector<Index>& handles) {
    Eigen::MatrixXd moved(mesh.num_vertices(), D);
    for (Index v = 0; v < mesh.num_vertices(); ++v)
        moved.row(v) = (R * mesh.vertices.row(v).transpose() + t).transpose();
    Eigen::MatrixXd targets(handles.size(), D);
    for (std::size_t k = 0; k < handles.size(); ++k) targets.row(k) = moved.row(handles[k]);
    ArapOptions options;
    options.tolerance = 1e-14;
    const ArapResult r = arap_deformation<D>(mesh, handles, targets, options);
    EXPECT_TRUE(r.converged) << r.stop << " after " << r.iterations;
    const double diagonal = bounding_box_diagonal(mesh.vertices);
    EXPECT_LE((r.positions - moved).cwiseAbs().maxCoeff(), 1e-11 * diagonal)
        << r.iterations << " iterations, " << r.stop;
    EXPECT_LE(r.energy, 1e-20 * diagonal * diagonal);
    EXPECT_GT(r.initial_energy, 0.0);
}

TEST(ArapDeformation, ReproducesARigidMotionExactly3D) {
    const SimplicialMesh mesh = grid_tetrahedra(8, 3, 3);
    const Mat<3> R =
        Eigen::AngleAxisd(2.1, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
    check_rigid_motion<3>(mesh, R, Vec<3>(3.0, -1.0, 0.25), end_vertices(mesh));
    // A few scattered handles only (not on one line): the motion is still determined.
    check_rigid_motion<3>(mesh, R, Vec<3>(0.5, 0.5, 0.5), {0, 17, 60, mesh.num_vertices() - 1});
}

TEST(ArapDeformation, ReproducesARigidMotionExactly2D) {
    const SimplicialMesh mesh = grid_triangles(12, 5);
    const Mat<2> R = Eigen::Rotation2Dd(2.8).toRotationMatrix();  // nearly a half turn
    check_rigid_motion<2>(mesh, R, Vec<2>(-4.0, 2.0), end_vertices(mesh));
}

TEST(ArapDeformation, HandlesStayAtTheirTargetsAndQDecreases) {
    // Bend: the right end turned by 90 degrees about z and moved up.
    const SimplicialMesh mesh = grid_tetrahedra(10, 2, 2);
    const std::vector<Index> handles = end_vertices(mesh);
    const Mat<3> R = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    Eigen::MatrixXd targets(handles.size(), 3);
    for (std::size_t k = 0; k < handles.size(); ++k) {
        const Eigen::Vector3d p = mesh.vertices.row(handles[k]).transpose();
        const Eigen::Vector3d q = p.x() > 0.5 ? Eigen::Vector3d(R * (p - Eigen::Vector3d(1, 0, 0)) +
                                                                Eigen::Vector3d(0.64, 0.64, 0))
                                              : p;
        targets.row(k) = q.transpose();
    }
    std::vector<double> energies;
    ArapOptions options;
    options.after_iteration = [&](const ArapIterate& it) {
        energies.push_back(it.energy);
        return false;
    };
    const ArapResult r = arap_deformation<3>(mesh, handles, targets, options);
    EXPECT_TRUE(r.converged) << r.stop;
    for (std::size_t k = 0; k < handles.size(); ++k)
        EXPECT_EQ(r.positions.row(handles[k]), targets.row(k));  // bit for bit
    ASSERT_EQ(energies.size(), std::size_t(r.iterations));
    EXPECT_LT(r.energy, r.initial_energy);
    // Every accepted iterate lowers Q (a raising accelerated point is replaced).
    double previous = r.initial_energy;
    for (double e : energies) {
        EXPECT_LE(e, previous * (1.0 + 1e-12));
        previous = e;
    }
    // The plain iteration reaches the same deformation.
    ArapOptions plain;
    plain.anderson_history = 0;
    plain.max_iterations = 20000;
    const ArapResult p = arap_deformation<3>(mesh, handles, targets, plain);
    EXPECT_TRUE(p.converged) << p.stop;
    EXPECT_EQ(p.rejected, 0);
    EXPECT_LE((p.positions - r.positions).cwiseAbs().maxCoeff(), 1e-6);
    EXPECT_NEAR(p.energy, r.energy, 1e-6 * r.energy);
}

TEST(ArapDeformation, CallerAndLimitsStopIt) {
    const SimplicialMesh mesh = grid_triangles(6, 6);
    const std::vector<Index> handles = {0, 6, 42, 48};
    Eigen::MatrixXd targets(4, 2);
    targets << 0, 0, 2, 0, 0, 1, 2, 1.5;
    ArapOptions options;
    options.after_iteration = [](const ArapIterate& it) { return it.iteration == 3; };
    ArapResult r = arap_deformation<2>(mesh, handles, targets, options);
    EXPECT_EQ(r.iterations, 3);
    EXPECT_FALSE(r.converged);
    options.after_iteration = nullptr;
    options.max_iterations = 2;
    r = arap_deformation<2>(mesh, handles, targets, options);
    EXPECT_EQ(r.iterations, 2);
    EXPECT_EQ(r.stop, "iteration limit");
    options.max_iterations = 0;
    r = arap_deformation<2>(mesh, handles, targets, options);
    EXPECT_EQ(r.iterations, 0);
    EXPECT_EQ(r.positions.row(48), targets.row(3));
}

TEST(ArapDeformation, RejectsBadHandles) {
    const SimplicialMesh mesh = grid_triangles(3, 3);
    const Eigen::MatrixXd two = Eigen::MatrixXd::Zero(2, 2);
    EXPECT_THROW(arap_deformation<2>(mesh, {0, 16}, two), InvalidArgumentError);
    EXPECT_THROW(arap_deformation<2>(mesh, {0, 0}, two), InvalidArgumentError);
    EXPECT_THROW(arap_deformation<2>(mesh, {0}, two), InvalidArgumentError);
    EXPECT_THROW(arap_deformation<2>(mesh, {}, Eigen::MatrixXd(0, 2)), InvalidArgumentError);
    EXPECT_THROW(arap_deformation<3>(mesh, {0, 1}, Eigen::MatrixXd::Zero(2, 3)),
                 InvalidArgumentError);
    ArapOptions bad;
    bad.tolerance = -1.0;
    EXPECT_THROW(arap_deformation<2>(mesh, {0, 1}, two, bad), InvalidArgumentError);
}

}  // namespace
}  // namespace sa
