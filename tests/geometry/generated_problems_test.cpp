// Generated mapping problems (tests/fixtures/generated_problems.h): feasible by construction.

#include "tests/fixtures/generated_problems.h"

#include <gtest/gtest.h>

#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/rest_frames.h"
#include "geometry/quality/map_quality.h"
#include "optim/errors.h"

namespace sa {
namespace {

MapQuality quality(const SimplicialMesh& rest, const Eigen::MatrixXd& map) {
    const RestFrames<3> frames = rest_frames<3>(rest);
    return map_quality<3>(linear_parts<3>(rest, frames, map), frames.volume);
}

TEST(GeneratedProblems, FixedBoundaryIsFeasibleAndTangled) {
    const SimplicialMesh rest = grid_tetrahedra(4, 4, 10);
    for (GeneratedDeformation d : {GeneratedDeformation::kTwist, GeneratedDeformation::kBend}) {
        const GeneratedProblem p = fixed_boundary_problem(rest, d, 1.5, 1.0, 3, 0.05);
        const MeshTopology t = mesh_topology(rest, "grid");
        // The handles are exactly the boundary, at the solution's positions.
        Index boundary = 0;
        for (Index v = 0; v < rest.num_vertices(); ++v) boundary += t.boundary_vertex[v];
        ASSERT_EQ(Index(p.handles.size()), boundary);
        for (Index h : p.handles) {
            EXPECT_TRUE(t.boundary_vertex[h]);
            EXPECT_EQ((p.initial.row(h) - p.solution.row(h)).norm(), 0.0);
        }
        // The solution is valid, the initial map is tangled.
        const MapQuality solved = quality(rest, p.solution), start = quality(rest, p.initial);
        EXPECT_EQ(solved.inverted + solved.degenerate, 0);
        EXPECT_GT(start.inverted, rest.num_simplices() / 10);
        // Flattened to 1/20: every simplex's conformal distortion is about 20.
        EXPECT_GT(solved.conformal.max, 10.0);
    }
}

TEST(GeneratedProblems, SeededAndDeterministic) {
    const SimplicialMesh rest = grid_tetrahedra(3, 3, 6);
    const auto a = fixed_boundary_problem(rest, GeneratedDeformation::kTwist, 1.0, 1.0, 5);
    const auto b = fixed_boundary_problem(rest, GeneratedDeformation::kTwist, 1.0, 1.0, 5);
    const auto c = fixed_boundary_problem(rest, GeneratedDeformation::kTwist, 1.0, 1.0, 6);
    EXPECT_EQ((a.initial - b.initial).norm(), 0.0);
    EXPECT_GT((a.initial - c.initial).norm(), 0.0);
}

TEST(GeneratedProblems, HandleSlabsMoveOnlyTheEnds) {
    const SimplicialMesh rest = grid_tetrahedra(3, 3, 12);
    const GeneratedProblem p = handle_slab_problem(rest, GeneratedDeformation::kTwist, 2.5, 0.1);
    const MapQuality solved = quality(rest, p.solution), start = quality(rest, p.initial);
    EXPECT_EQ(solved.inverted + solved.degenerate, 0);
    EXPECT_GT(start.inverted, 0);
    std::vector<unsigned char> handle(rest.num_vertices(), 0);
    for (Index h : p.handles) handle[h] = 1;
    for (Index v = 0; v < rest.num_vertices(); ++v) {
        const double z = rest.vertices(v, 2), length = rest.vertices.col(2).maxCoeff();
        EXPECT_EQ(bool(handle[v]), z <= 0.1 * length + 1e-12 || z >= 0.9 * length - 1e-12);
        if (!handle[v]) EXPECT_EQ((p.initial.row(v) - rest.vertices.row(v)).norm(), 0.0);
    }
}

TEST(GeneratedProblems, RejectsADeformationThatInvertsTheRestMesh) {
    // Bent into more than a full turn of radius smaller than the bar's thickness.
    EXPECT_THROW(
        fixed_boundary_problem(grid_tetrahedra(4, 4, 4), GeneratedDeformation::kBend, 20.0, 1.0, 1),
        InvalidArgumentError);
    // A twist needs a mesh in space.
    EXPECT_THROW(deform(grid_triangles(2, 2).vertices, GeneratedDeformation::kTwist, 1.0),
                 InvalidArgumentError);
}

}  // namespace
}  // namespace sa
