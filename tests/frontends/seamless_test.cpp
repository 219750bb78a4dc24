#include "frontends/seamless/seamless_parameterization.h"

#include "frontends/seamless/cone_obstruction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "frontends/seamless/frame_field.h"
#include "geometry/mesh/mesh_generators.h"
#include "optim/errors.h"

namespace sa {
namespace {

/// A per-face field given as vectors in space, as a file would give it.
FrameFieldInput as_vectors(const RestFrames<2>& frames, const std::vector<Mat<2>>& matrices) {
    const auto [u, v] = frame_vectors(frames, matrices);
    return {u, v, {}};
}

TEST(Seamless, AFieldFromAKnownParameterizationComesBackUpToScale) {
    // The torus's angle map (i / nu, j / nv): a gradient field without singularities, with
    // different lengths along u and v.
    const int nu = 24, nv = 12;
    const SimplicialMesh torus = torus_triangles(nu, nv);
    const RestFrames<2> frames = rest_frames<2>(torus);
    std::vector<Mat<2>> known(torus.num_simplices());
    for (Index f = 0; f < torus.num_simplices(); ++f) {
        Eigen::Matrix<double, 2, 3> uv;
        for (int k = 0; k < 3; ++k) {
            const Index v = torus.simplices(f, k);
            uv.col(k) << double(v % nu) / nu, double(v / nu) / nv;
            for (int c = 0; k > 0 && c < 2; ++c) uv(c, k) -= std::round(uv(c, k) - uv(c, 0));
        }
        known[f] = linear_part<2>(frames, f, uv);
    }
    const SeamlessResult r = seamless_parameterization(torus, as_vectors(frames, known));
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_TRUE(r.singularities_before.empty());
    EXPECT_LT(r.curl_stats_before.max, 1e-9);
    EXPECT_EQ(r.plain.quality.inverted, 0);
    const RestFrames<2> cut_frames = rest_frames<2>(r.result.map.cut.mesh);
    const std::vector<Mat<2>> J =
        linear_parts<2>(r.result.map.cut.mesh, cut_frames, r.result.map.uv);
    // Up to scale and the combing's quarter turns of each chart (seamless_poisson.h).
    const double c = J[0].norm() / known[0].norm();
    for (Index f = 0; f < torus.num_simplices(); ++f) {
        const Mat<2> expected = c * quarter_turns(r.result.map.chart_turns[f]) * known[f];
        EXPECT_LT((J[f] - expected).norm(), 1e-6 * expected.norm()) << "face " << f;
    }
}

TEST(Seamless, ANoisyFieldBecomesIntegrableWithItsSingularities) {
    const SimplicialMesh sphere = sphere_triangles(6);
    const MeshTopology topology = mesh_topology(sphere, "sphere");
    const RestFrames<2> frames = rest_frames<2>(sphere);
    const Eigen::MatrixXd smooth = smoothest_cross_field(sphere, topology);
    const std::vector<Singularity> expected = cross_field_singularities(sphere, topology, smooth);
    std::vector<Mat<2>> noisy = frame_matrices(frames, smooth);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> angle(-0.1, 0.1), stretch(0.85, 1.15);
    for (Mat<2>& A : noisy) {
        const double a = angle(rng);
        Mat<2> R;
        R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
        A = Eigen::Vector2d(stretch(rng), stretch(rng)).asDiagonal() * A * R;
    }
    const SeamlessResult r = seamless_parameterization(sphere, as_vectors(frames, noisy));
    ASSERT_EQ(r.singularities_before.size(), expected.size());  // the noise kept them
    EXPECT_GT(r.curl_stats_before.max, 1e-2);                   // and is far from integrable
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_TRUE(r.integrable.assembled);
    EXPECT_LT(r.curl_stats_after.max, 1e-6);
    EXPECT_TRUE(r.singularities_kept);
    EXPECT_TRUE(r.matchings_kept);
    EXPECT_EQ(r.result.quality.inverted, 0);
    EXPECT_LT(r.result.map.max_seam_mismatch, 1e-6);
    double index_sum = 0.0;
    for (const Singularity& s : r.singularities_after) index_sum += s.index;
    EXPECT_DOUBLE_EQ(index_sum, 2.0);  // Poincaré-Hopf on the sphere
}

TEST(Seamless, WithoutAFieldTheSmoothestCrossFieldIsUsed) {
    SimplicialMesh grid = grid_triangles(12, 12);  // planar: gets z = 0
    const SeamlessResult r = seamless_parameterization(grid, std::nullopt);
    EXPECT_EQ(r.field_source, "smoothest cross field");
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_TRUE(r.singularities_before.empty());
}

TEST(Seamless, ATorusWithOnlyAPlusMinusQuarterPairIsInfeasible) {
    const SimplicialMesh torus = torus_triangles(16, 8);
    const MeshTopology t = mesh_topology(torus, "torus");
    const std::string reason = seamless_cone_obstruction(torus, t, {{3, 0.25}, {40, -0.25}});
    EXPECT_NE(reason.find("vertex 3"), std::string::npos) << reason;
    EXPECT_NE(reason.find("vertex 40"), std::string::npos) << reason;
    // Other configurations are not ruled out: two pairs, a +-1/2 pair, none, another genus.
    EXPECT_EQ(seamless_cone_obstruction(torus, t, {{3, 0.25}, {9, -0.25}, {40, 0.25}, {50, -0.25}}),
              "");
    EXPECT_EQ(seamless_cone_obstruction(torus, t, {{3, 0.5}, {40, -0.5}}), "");
    EXPECT_EQ(seamless_cone_obstruction(torus, t, {}), "");
    const SimplicialMesh sphere = sphere_triangles(4);
    EXPECT_EQ(
        seamless_cone_obstruction(sphere, mesh_topology(sphere, "sphere"), {{0, 0.25}, {1, -0.25}}),
        "");
}

// The repair's mechanics (local_field_repair.h) on a generated torus whose result is marked as
// folded on two faces: a region around them is smoothed for the field only, the pipeline runs
// again, and the result is verified on the input surface, whose positions stay.
TEST(Seamless, LocalRepairSmoothsTheFieldsGeometryAndKeepsTheSurface) {
    const SimplicialMesh torus = torus_triangles(24, 12);
    SeamlessOptions options;
    options.local_repair = false;
    SeamlessResult folded = seamless_parameterization(torus, std::nullopt, options);
    ASSERT_TRUE(folded.success) << folded.message;
    for (Index f : {Index(100), Index(101)}) folded.result.quality.per_simplex[f].inverted = true;
    folded.success = false;
    options.local_repair = true;
    const SeamlessResult r = repair_folded_field(folded, options, {});
    ASSERT_TRUE(r.repair.ran);
    EXPECT_EQ(r.repair.folded_faces, 2);
    ASSERT_FALSE(r.repair.attempts.empty());
    const FieldRepairAttempt& a = r.repair.attempts.front();
    EXPECT_GT(a.vertices_moved, 0);
    EXPECT_GT(a.largest_move, 0.0);
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_TRUE(r.repair.success);
    EXPECT_TRUE(r.singularities_kept);
    EXPECT_EQ(r.result.quality.inverted, 0);
    EXPECT_EQ(r.surface.vertices, torus.vertices);
    // The cut mesh the (u, v) belong to has the input positions.
    const CutMesh& cut = r.result.map.cut;
    for (Index c = 0; c < cut.mesh.num_vertices(); ++c)
        EXPECT_EQ(cut.mesh.vertices.row(c), torus.vertices.row(cut.original_vertex[c]));
    EXPECT_NE(r.message.find("without the repair"), std::string::npos) << r.message;
}

TEST(Seamless, BadInputIsRejected) {
    const SimplicialMesh sphere = sphere_triangles(4);
    FrameFieldInput wrong;
    wrong.u = Eigen::MatrixXd::Ones(sphere.num_simplices() - 1, 3);
    EXPECT_THROW(seamless_parameterization(sphere, wrong), InvalidArgumentError);
    // Three triangles on one edge: non-manifold.
    SimplicialMesh fan;
    fan.vertices.resize(5, 3);
    fan.vertices << 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0, 0.5, 0, 1;
    fan.simplices.resize(3, 3);
    fan.simplices << 0, 1, 2, 1, 0, 3, 0, 1, 4;
    EXPECT_THROW(seamless_parameterization(fan, std::nullopt), InputError);
}

}  // namespace
}  // namespace sa
