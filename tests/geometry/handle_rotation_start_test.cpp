#include "geometry/maps/handle_rotation_start.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "geometry/maps/arap_deformation.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/quality/map_quality.h"
#include "tests/fixtures/bar_deformation.h"

namespace sa {
namespace {

struct Problem {
    SimplicialMesh mesh;
    std::vector<Index> handles;
    Eigen::MatrixXd targets;
};

template <int D>
struct Runs {
    ArapResult rotated, rest;
    MapQuality rotated_quality;
};

template <int D>
Runs<D> run_both(const Problem& p) {
    ArapOptions options;
    options.max_iterations = 3000;
    Runs<D> runs;
    runs.rotated = arap_deformation<D>(p.mesh, p.handles, p.targets, options);
    options.rotation_start = false;
    runs.rest = arap_deformation<D>(p.mesh, p.handles, p.targets, options);
    const RestFrames<D> frames = rest_frames<D>(p.mesh);
    runs.rotated_quality =
        map_quality<D>(linear_parts<D>(p.mesh, frames, runs.rotated.positions), frames.volume);
    return runs;
}

/// The class the start is for: large rotations of handle slabs. From the rotations' start the
/// iterations converge to an unfolded pose, in few iterations, at a Q no higher than from the
/// rest shape (where the rest shape's run ends folded, lower).
template <int D>
void expect_better_start(const Problem& p, const std::string& what, int max_iterations) {
    SCOPED_TRACE(what);
    const Runs<D> runs = run_both<D>(p);
    EXPECT_EQ(runs.rotated.start.rfind("handle rotations", 0), 0u) << runs.rotated.start;
    EXPECT_TRUE(runs.rotated.converged) << runs.rotated.stop;
    EXPECT_LE(runs.rotated.iterations, max_iterations);
    EXPECT_EQ(runs.rotated_quality.inverted, 0);
    EXPECT_LE(runs.rotated.energy, runs.rest.energy * (1.0 + 1e-7));
    std::printf("%s: %d iterations (rest shape: %d, %s), Q %.9g (%.9g)\n", what.c_str(),
                runs.rotated.iterations, runs.rest.iterations, runs.rest.stop.c_str(),
                runs.rotated.energy, runs.rest.energy);
}

Problem bar(BarPose pose, const BarDeformationOptions& options) {
    BarDeformation b = bar_deformation(pose, options);
    return {std::move(b.mesh), std::move(b.handles), std::move(b.targets)};
}

TEST(HandleRotationStart, TwistsAndBendsOfBars) {
    for (const auto& [length_cells, cross_cells] : {std::pair{12, 3}, std::pair{20, 4}}) {
        for (double degrees : {90.0, 150.0, 180.0}) {
            BarDeformationOptions options;
            options.length_cells = length_cells;
            options.cross_cells = cross_cells;
            options.twist_degrees = degrees;
            options.bend_degrees = degrees / 2.0;
            const std::string size =
                std::to_string(length_cells) + " x " + std::to_string(cross_cells);
            expect_better_start<3>(bar(BarPose::kTwist, options),
                                   "twist " + std::to_string(int(degrees)) + ", " + size, 80);
            expect_better_start<3>(bar(BarPose::kBend, options),
                                   "bend " + std::to_string(int(degrees / 2)) + ", " + size, 80);
        }
    }
}

/// A strip [0, 5] x [0, 1] of triangles, its left column fixed and its right column turned by
/// `degrees` and carried to the end of the circular arc of the strip's length.
Problem bent_strip(double degrees) {
    Problem p;
    p.mesh = grid_triangles(30, 6);
    p.mesh.vertices.col(0) *= 5.0;
    const double theta = degrees * M_PI / 180.0, radius = 5.0 / theta;
    const Mat<2> R = Eigen::Rotation2Dd(theta).toRotationMatrix();
    const Vec<2> end(radius * std::sin(theta), 0.5 + radius * (1.0 - std::cos(theta)));
    std::vector<Vec<2>> targets;
    for (Index v = 0; v < p.mesh.num_vertices(); ++v) {
        const Vec<2> x = p.mesh.vertices.row(v).head<2>().transpose();
        if (x[0] < 1e-12) {
            p.handles.push_back(v);
            targets.push_back(x);
        } else if (x[0] > 5.0 - 1e-12) {
            p.handles.push_back(v);
            targets.push_back(R * (x - Vec<2>(5.0, 0.5)) + end);
        }
    }
    p.targets.resize(targets.size(), 2);
    for (std::size_t k = 0; k < targets.size(); ++k) p.targets.row(k) = targets[k].transpose();
    return p;
}

// (Bent by 270 degrees, the rotations' start turns the strip's far end back by 90 degrees, the
// shorter way, and ends at a higher Q than the rest shape's: the header's limit.)
TEST(HandleRotationStart, BentStrips2D) {
    for (double degrees : {90.0, 135.0, 180.0}) {
        expect_better_start<2>(bent_strip(degrees), "strip " + std::to_string(int(degrees)), 80);
    }
}

// One group moved rigidly: the start is that rigid motion, exactly.
TEST(HandleRotationStart, OneRigidGroupGivesItsMotion) {
    const SimplicialMesh mesh = grid_tetrahedra(6, 3, 2);
    const Mat<3> R =
        Eigen::AngleAxisd(2.5, Eigen::Vector3d(0.3, -1.0, 2.0).normalized()).toRotationMatrix();
    const Vec<3> t(1.0, 2.0, -3.0);
    std::vector<unsigned char> fixed(mesh.num_vertices(), 0);
    Eigen::MatrixXd start = mesh.vertices, moved = mesh.vertices;
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        moved.row(v) = (R * mesh.vertices.row(v).transpose() + t).transpose();
        if (mesh.vertices(v, 0) < 1e-12) {
            fixed[v] = 1;
            start.row(v) = moved.row(v);
        }
    }
    const RestFrames<3> frames = rest_frames<3>(mesh);
    const VertexRecovery<3> recovery(mesh, frames, fixed);
    const HandleRotationStart s = handle_rotation_start<3>(mesh, frames, recovery, start);
    EXPECT_EQ(s.groups, 1);
    EXPECT_EQ(s.rotation_groups, 1);
    EXPECT_LT((s.positions - moved).cwiseAbs().maxCoeff(), 1e-12);
}

// Handles that determine no rotation (single vertices, a line of vertices in 3D) still give a
// start, with the handles at their targets; ARAP from it reproduces a rigid motion.
TEST(HandleRotationStart, GroupsWithoutARotation) {
    const SimplicialMesh mesh = grid_tetrahedra(6, 3, 3);
    const Mat<3> R = Eigen::AngleAxisd(1.2, Eigen::Vector3d::UnitY()).toRotationMatrix();
    std::vector<Index> handles;
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        const Vec<3> x = mesh.vertices.row(v).transpose();
        if (x[1] < 1e-12 && x[2] < 1e-12) handles.push_back(v);  // a line along x
    }
    handles.push_back(mesh.num_vertices() - 1);  // a corner, alone
    Eigen::MatrixXd targets(handles.size(), 3);
    for (std::size_t k = 0; k < handles.size(); ++k)
        targets.row(k) = (R * mesh.vertices.row(handles[k]).transpose()).transpose();
    std::vector<unsigned char> fixed(mesh.num_vertices(), 0);
    Eigen::MatrixXd start = mesh.vertices;
    for (std::size_t k = 0; k < handles.size(); ++k) {
        fixed[handles[k]] = 1;
        start.row(handles[k]) = targets.row(k);
    }
    const RestFrames<3> frames = rest_frames<3>(mesh);
    const VertexRecovery<3> recovery(mesh, frames, fixed);
    const HandleRotationStart s = handle_rotation_start<3>(mesh, frames, recovery, start);
    EXPECT_EQ(s.groups, 2);
    EXPECT_EQ(s.rotation_groups, 0);
    ASSERT_TRUE(s.positions.allFinite());
    for (std::size_t k = 0; k < handles.size(); ++k)
        EXPECT_EQ(s.positions.row(handles[k]), targets.row(k));
    ArapOptions options;
    options.tolerance = 1e-13;
    options.max_iterations = 3000;
    const ArapResult r = arap_deformation<3>(mesh, handles, targets, options);
    EXPECT_TRUE(r.converged) << r.stop;
    Eigen::MatrixXd moved = (mesh.vertices * R.transpose());
    EXPECT_LT((r.positions - moved).cwiseAbs().maxCoeff(), 1e-9);
}

}  // namespace
}  // namespace sa
