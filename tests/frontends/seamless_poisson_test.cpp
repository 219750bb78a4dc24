#include "frontends/seamless/seamless_poisson.h"

#include <gtest/gtest.h>

#include <cmath>

#include "frontends/seamless/cross_field.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/rest_frames.h"

namespace sa {
namespace {

// Every face of the result has the target Jacobian (so the map is the target up to a rigid motion
// per connected part and the seam transitions).
void expect_jacobians(const SimplicialMesh& mesh, const SeamlessMap& map,
                      const std::vector<Mat<2>>& target) {
    const RestFrames<2> frames = rest_frames<2>(mesh);
    for (Index f = 0; f < mesh.num_simplices(); ++f) {
        Eigen::Matrix<double, 2, 3> corners;
        for (int k = 0; k < 3; ++k)
            corners.col(k) = map.uv.row(map.cut.mesh.simplices(f, k)).transpose();
        EXPECT_LT((linear_part<2>(frames, f, corners) - target[f]).norm(), 1e-6) << "face " << f;
    }
    EXPECT_LT(map.max_seam_mismatch, 1e-6);
}

TEST(SeamlessPoisson, RecoversTheAngleParameterizationOfATorus) {
    const int nu = 24, nv = 12;
    const SimplicialMesh torus = torus_triangles(nu, nv);
    const MeshTopology t = mesh_topology(torus, "torus");
    // The known map: (i / nu, j / nv) per vertex (i, j), unwrapped within each face.
    const RestFrames<2> frames = rest_frames<2>(torus);
    std::vector<Mat<2>> jacobians(torus.num_simplices());
    for (Index f = 0; f < torus.num_simplices(); ++f) {
        Eigen::Matrix<double, 2, 3> uv;
        for (int k = 0; k < 3; ++k) {
            const Index v = torus.simplices(f, k);
            uv.col(k) << double(v % nu) / nu, double(v / nu) / nv;
            if (k > 0) {  // the periodic wrap: take the copy next to corner 0
                for (int c = 0; c < 2; ++c) uv(c, k) -= std::round(uv(c, k) - uv(c, 0));
            }
        }
        jacobians[f] = linear_part<2>(frames, f, uv);
    }
    const std::vector<unsigned char> cut = cut_graph(torus, t, {});
    const SeamlessMap map =
        seamless_poisson(torus, t, cut, std::vector<int>(t.interior_facets.size(), 0), jacobians);
    expect_jacobians(torus, map, jacobians);
}

TEST(SeamlessPoisson, AQuarterTurnSeamFollowsTheMatching) {
    // A flat square whose right half is mapped turned by 90 degrees: the charts differ by a
    // quarter turn across the middle, which the matching of the aligned cross field tells.
    const SimplicialMesh square = grid_triangles(8, 8);
    const MeshTopology t = mesh_topology(square, "square");
    Mat<2> quarter;
    quarter << 0.0, -1.0, 1.0, 0.0;
    std::vector<Mat<2>> jacobians(square.num_simplices());
    std::vector<unsigned char> right(square.num_simplices());
    Eigen::MatrixXd directions = Eigen::MatrixXd::Zero(square.num_simplices(), 3);
    for (Index f = 0; f < square.num_simplices(); ++f) {
        double x = 0.0;
        for (int k = 0; k < 3; ++k) x += square.vertices(square.simplices(f, k), 0) / 3.0;
        right[f] = x > 0.5;
        jacobians[f] = right[f] ? quarter : Mat<2>::Identity();
        const Vec<2> u = jacobians[f].inverse() * Vec<2>(1.0, 0.0);  // the direction mapped to +u
        directions.row(f) << u.x(), u.y(), 0.0;
    }
    const std::vector<int> matching = cross_field_matchings(square, t, directions);
    std::vector<unsigned char> cut(t.interior_facets.size(), 0);
    for (std::size_t i = 0; i < cut.size(); ++i) {
        const auto& s = t.interior_facets[i].simplex;
        cut[i] = right[s[0]] != right[s[1]];
        EXPECT_EQ(matching[i] != 0, bool(cut[i])) << "facet " << i;
    }
    const SeamlessMap map = seamless_poisson(square, t, cut, matching, jacobians);
    expect_jacobians(square, map, jacobians);
}

}  // namespace
}  // namespace sa
