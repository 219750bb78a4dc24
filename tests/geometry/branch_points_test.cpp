#include "geometry/quality/branch_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/rest_frames.h"
#include "geometry/mesh/submesh.h"
#include "geometry/quality/map_quality.h"

namespace sa {
namespace {

using C = std::complex<double>;

// The unit square's grid mapped by f(z) = (z - z0)^tau: a fold at z0 that loops around turn tau
// times.
Eigen::MatrixXd power_map(const SimplicialMesh& mesh, C z0, int tau) {
    Eigen::MatrixXd x(mesh.num_vertices(), 2);
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        const C f = std::pow(C(mesh.vertices(v, 0), mesh.vertices(v, 1)) - z0, tau);
        x.row(v) << f.real(), f.imag();
    }
    return x;
}

std::vector<Index> over(const SimplicialMesh& mesh, const Eigen::MatrixXd& x, double delta) {
    const RestFrames<2> frames = rest_frames<2>(mesh);
    const MapQuality q = map_quality<2>(linear_parts<2>(mesh, frames, x), frames.volume);
    std::vector<Index> bad;
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        const SimplexQuality& p = q.per_simplex[s];
        if (p.inverted || p.degenerate || p.conformal >= delta) bad.push_back(s);
    }
    return bad;
}

TEST(BranchPoints, TurningAndWindingNumbersOfPolygons) {
    Eigen::MatrixXd square(4, 2);
    square << 0, 0, 1, 0, 1, 1, 0, 1;
    EXPECT_NEAR(turning_number({0, 1, 2, 3}, square), 1.0, 1e-12);
    EXPECT_NEAR(turning_number({0, 3, 2, 1}, square), -1.0, 1e-12);
    EXPECT_NEAR(turning_number({0, 1, 1, 2, 3, 0}, square), 1.0, 1e-12);  // repeated points
    EXPECT_NEAR(winding_number({0, 1, 2, 3}, square, Eigen::Vector2d(0.5, 0.5)), 1.0, 1e-12);
    EXPECT_NEAR(winding_number({0, 1, 2, 3}, square, Eigen::Vector2d(1.5, 0.5)), 0.0, 1e-12);
    // A polygon that goes twice around the origin.
    Eigen::MatrixXd twice(10, 2);
    for (int k = 0; k < 10; ++k)
        twice.row(k) << std::cos(4 * M_PI * k / 10), std::sin(4 * M_PI * k / 10);
    std::vector<Index> loop(10);
    for (int k = 0; k < 10; ++k) loop[k] = k;
    EXPECT_NEAR(turning_number(loop, twice), 2.0, 1e-12);
    EXPECT_NEAR(winding_number(loop, twice, Eigen::Vector2d::Zero()), 2.0, 1e-12);
}

TEST(BranchPoints, AFoldThatTurnsLoopsTwiceOrThriceIsFoundAndComposedAway) {
    const SimplicialMesh mesh = grid_triangles(60, 60);
    const MeshTopology topology = mesh_topology(mesh, "grid");
    const C z0(0.514, 0.487);
    for (int tau : {2, 3}) {
        SCOPED_TRACE("tau = " + std::to_string(tau));
        const Eigen::MatrixXd x = power_map(mesh, z0, tau);
        const std::vector<Index> bad = over(mesh, x, 2.5);
        ASSERT_FALSE(bad.empty());
        EXPECT_EQ(count_unrepairable_folds(mesh, topology, x, bad, 4), 1);
        const std::vector<BranchPoint> points = find_branch_points(mesh, topology, x, bad, 4);
        ASSERT_EQ(points.size(), 1u);
        EXPECT_EQ(points[0].turning, tau);
        EXPECT_LT(points[0].image.norm(), 1e-3);  // f(z0) = 0
        // G(w) = w^(1/tau) up to a similarity: G o f = z - z0, an affine map of the grid, but
        // next to z0 (where the integration meets the fold).
        const Eigen::MatrixXd y = remove_branch_points(mesh, topology, x, points);
        const std::vector<Index> still = over(mesh, y, 1.01);
        EXPECT_LT(still.size(), 100u);
        EXPECT_EQ(count_unrepairable_folds(mesh, topology, y, still, 4), 0);
        // Its bounding box has the start's diagonal and centre.
        EXPECT_NEAR(bounding_box_diagonal(y), bounding_box_diagonal(x), 1e-9);
        const Eigen::RowVector2d cx = 0.5 * (x.colwise().minCoeff() + x.colwise().maxCoeff()),
                                 cy = 0.5 * (y.colwise().minCoeff() + y.colwise().maxCoeff());
        EXPECT_LT((cx - cy).norm(), 1e-9);
    }
}

}  // namespace
}  // namespace sa
