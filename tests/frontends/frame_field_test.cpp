#include "frontends/seamless/frame_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "frontends/seamless/cut_graph.h"
#include "geometry/mesh/mesh_generators.h"
#include "optim/errors.h"

namespace sa {
namespace {

/// A bumpy grid in space: a surface that is not flat, so the frames differ from face to face.
SimplicialMesh bumpy_grid() {
    SimplicialMesh mesh = grid_triangles(10, 8);
    mesh.vertices.conservativeResize(Eigen::NoChange, 3);
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        const double x = mesh.vertices(v, 0), y = mesh.vertices(v, 1);
        mesh.vertices(v, 2) = 0.2 * std::sin(3.0 * x) * std::cos(2.0 * y);
    }
    return mesh;
}

TEST(FrameField, TheCurlOfAGradientFieldIsZero) {
    const SimplicialMesh mesh = bumpy_grid();
    const MeshTopology topology = mesh_topology(mesh, "grid");
    const RestFrames<2> frames = rest_frames<2>(mesh);
    // Any per-vertex (u, v): its Jacobians are the gradients of two piecewise linear functions.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> noise(-0.05, 0.05);
    Eigen::MatrixXd uv(mesh.num_vertices(), 2);
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        uv.row(v) << mesh.vertices(v, 0) + noise(rng), mesh.vertices(v, 1) + noise(rng);
    }
    std::vector<Mat<2>> jacobians(mesh.num_simplices());
    for (Index f = 0; f < mesh.num_simplices(); ++f) {
        Eigen::Matrix<double, 2, 3> corners;
        for (int k = 0; k < 3; ++k) corners.col(k) = uv.row(mesh.simplices(f, k)).transpose();
        jacobians[f] = linear_part<2>(frames, f, corners);
    }
    const std::vector<int> no_turns(topology.interior_facets.size(), 0);
    const Eigen::VectorXd curl = edge_curl(mesh, topology, frames, jacobians, no_turns);
    EXPECT_LT(curl.maxCoeff(), 1e-12);
    // A rotated copy on one face is not curl free: the test can fail.
    jacobians[7] = quarter_turns(1) * jacobians[7];
    EXPECT_GT(edge_curl(mesh, topology, frames, jacobians, no_turns).maxCoeff(), 0.1);
}

TEST(FrameField, CrossesAndFramesBecomePositivelyOrientedMatrices) {
    const SimplicialMesh mesh = bumpy_grid();
    const RestFrames<2> frames = rest_frames<2>(mesh);
    const Index nf = mesh.num_simplices();
    Eigen::MatrixXd u(nf, 3), v(nf, 3);
    for (Index f = 0; f < nf; ++f) {
        u.row(f) = frames.axes[f].col(0).transpose() * 2.0;
        v.row(f) = -frames.axes[f].col(1).transpose();  // left-handed: flipped to +y
    }
    const std::vector<Mat<2>> cross = frame_matrices(frames, u);
    const std::vector<Mat<2>> frame = frame_matrices(frames, u, v);
    Mat<2> expected_cross, expected_frame;
    expected_cross << 2.0, 0.0, 0.0, 2.0;
    expected_frame << 2.0, 0.0, 0.0, 1.0;
    for (Index f = 0; f < nf; ++f) {
        EXPECT_LT((cross[f] - expected_cross).norm(), 1e-12);
        EXPECT_LT((frame[f] - expected_frame).norm(), 1e-12);
    }
    const Eigen::MatrixXd directions = frame_cross_directions(frames, frame);
    EXPECT_LT((directions.row(5) - frames.axes[5].col(0).transpose()).norm(), 1e-12);

    v.row(3) = u.row(3);  // parallel vectors: no frame
    EXPECT_THROW(frame_matrices(frames, u, v), InputError);
}

}  // namespace
}  // namespace sa
