#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>

#include "frontends/simplex_assembly/map_solve.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/mesh_topology.h"
#include "scrambled_problem.h"
#include "tests/fixtures/generated_problems.h"

namespace sa {
namespace {

// A grid with its boundary as handles and a few interior vertices pushed across their
// neighbours: separate, local folds, as after moving a few handles.
MappingProblem local_folds(const SimplicialMesh& mesh, const std::vector<Index>& pushed,
                           double amount) {
    MappingProblem p;
    p.mesh = mesh;
    p.initial = mesh.vertices;
    const MeshTopology t = mesh_topology(mesh, "grid");
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        if (t.boundary_vertex[v]) p.handles.push_back(v);
    }
    for (Index v : pushed) p.initial(v, 0) += amount;
    return p;
}

SimplexAssemblyOptions submesh_options(int threads) {
    SimplexAssemblyOptions options;
    options.mode = SolveMode::kSubmesh;
    options.num_threads = threads;
    options.rings = 2;
    options.start_iterations = 0;  // start from the folds themselves, so that regions are solved
    return options;
}

TEST(SubmeshMode, RepairsSeparateFoldsIn2DAndIsVerified) {
    const int n = 40;  // vertex (i, j) = j * 41 + i
    const MappingProblem p =
        local_folds(grid_triangles(n, n), {10 * 41 + 10, 30 * 41 + 25, 12 * 41 + 33}, 0.06);
    const SimplexAssemblyResult r = run_simplex_assembly(p, submesh_options(0));
    EXPECT_GT(r.initial_quality.inverted, 0);
    EXPECT_EQ(r.mode, SolveMode::kSubmesh);
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_EQ(r.verification.inverted, 0);
    ASSERT_FALSE(r.submesh.rounds.empty());
    EXPECT_EQ(r.submesh.rounds[0].regions, 3) << r.submesh.describe();  // three separate folds
    EXPECT_LT(r.submesh.largest_submesh, p.mesh.num_simplices() / 4);   // local, not the mesh
}

TEST(SubmeshMode, RepairsA3DFold) {
    const int n = 8;  // vertex (i, j, k) = (k * 9 + j) * 9 + i
    const MappingProblem p = local_folds(grid_tetrahedra(n, n, n), {(4 * 9 + 4) * 9 + 4}, 0.2);
    const SimplexAssemblyResult r = run_simplex_assembly(p, submesh_options(0));
    EXPECT_GT(r.initial_quality.inverted, 0);
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_EQ(r.mode, SolveMode::kSubmesh);
}

TEST(SubmeshMode, SameOutputOnOneAndTwoThreads) {
    const int n = 40;
    const MappingProblem p =
        local_folds(grid_triangles(n, n), {10 * 41 + 10, 30 * 41 + 25, 12 * 41 + 33}, 0.06);
    const SimplexAssemblyResult a = run_simplex_assembly(p, submesh_options(1));
    const SimplexAssemblyResult b = run_simplex_assembly(p, submesh_options(2));
    ASSERT_TRUE(a.success && b.success) << a.message << " / " << b.message;
    ASSERT_EQ(a.positions.size(), b.positions.size());
    EXPECT_EQ(
        std::memcmp(a.positions.data(), b.positions.data(), sizeof(double) * a.positions.size()),
        0);
    EXPECT_EQ(a.submesh.solves, b.submesh.solves);
}

// A bar whose top face is turned by 120 degrees about its axis, the bottom fixed: only the
// tetrahedra under the top face fold, but a valid map has to twist the whole bar. The
// accelerated ARAP iterations of the start do that before any submesh is solved.
TEST(SubmeshMode, TheStartSpreadsALargeHandleRotation) {
    MappingProblem p;
    p.mesh = grid_tetrahedra(3, 3, 12);
    p.initial = p.mesh.vertices;
    const double top = p.mesh.vertices.col(2).maxCoeff();
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(2.0 * M_PI / 3.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::RowVector3d axis(0.125, 0.125, 0.0);  // the bar is [0, 0.25]^2 x [0, 1]
    for (Index v = 0; v < p.mesh.num_vertices(); ++v) {
        const double z = p.mesh.vertices(v, 2);
        if (z == 0.0 || z == top) p.handles.push_back(v);
        if (z == top) {
            p.initial.row(v) =
                (turn * (p.mesh.vertices.row(v) - axis).transpose()).transpose() + axis;
        }
    }
    SimplexAssemblyOptions options;
    options.mode = SolveMode::kSubmesh;
    options.distortion = DistortionType::kIsometric;
    options.num_threads = 1;
    // The bar's 648 tetrahedra are fewer than the auto mode solves in full, so by default the
    // regions around its folds are solved as they are (checked at the end); a lower limit makes
    // it a large mesh, whose start runs.
    options.auto_full_tetrahedra = 100;
    const SimplexAssemblyResult a = run_simplex_assembly(p, options);
    EXPECT_GT(a.initial_quality.inverted, 0);
    ASSERT_TRUE(a.success) << a.message;
    EXPECT_EQ(a.submesh.start_bad, 0) << a.submesh.describe();
    // The local/global iterations from the handles' rotations carried through the bar.
    EXPECT_EQ(a.submesh.start.iterate, StartIterate::kLocalGlobal) << a.submesh.start.describe();
    EXPECT_FALSE(a.submesh.start.similarity);
    EXPECT_TRUE(a.submesh.start.from_handle_rotations) << a.submesh.start.describe();
    EXPECT_FALSE(a.submesh.start.untangled);
    EXPECT_EQ(a.submesh.solves, 0);
    EXPECT_TRUE(a.stages.vertex_stage_ran()) << a.message;  // the start moved every vertex

    options.num_threads = 2;
    const SimplexAssemblyResult b = run_simplex_assembly(p, options);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    EXPECT_EQ(
        std::memcmp(a.positions.data(), b.positions.data(), sizeof(double) * a.positions.size()),
        0);

    options.until_valid = true;  // stops at the first valid iterate, no vertex stage
    const SimplexAssemblyResult c = run_simplex_assembly(p, options);
    ASSERT_TRUE(c.success) << c.message;
    EXPECT_LE(c.submesh.start_iterations, a.submesh.start_iterations);
    EXPECT_EQ(c.stages.last(Stage::kVertexStage), nullptr);

    // Small regions: once the handles' rotations are taken, the iterations run from them all the
    // same, and leave nothing to repair.
    options = SimplexAssemblyOptions{};
    options.mode = SolveMode::kSubmesh;
    options.distortion = DistortionType::kIsometric;
    const SimplexAssemblyResult d = run_simplex_assembly(p, options);
    ASSERT_TRUE(d.success) << d.message;
    EXPECT_TRUE(d.submesh.start.iterate == StartIterate::kHandleRotations ||
                d.submesh.start.from_handle_rotations)
        << d.submesh.start.describe();
    EXPECT_EQ(d.submesh.solves, 0);
}

// A bar whose end slabs are handles twisted by half a turn against each other, every other vertex
// at rest (tests/fixtures/generated_problems.h): from that initial map, region solves (small
// meshes) and the local/global iterations then the untangling (large ones) ended with every
// tetrahedron positive but edges wrapped twice (branch points), or at the time limit with folds.
// The start from the handles' rotations carried through the bar has no bad simplex.
TEST(SubmeshMode, HandlesTwistedByHalfATurnGiveALocallyInjectiveMap) {
    for (int n : {4, 6}) {
        const GeneratedProblem g = handle_slab_problem(grid_tetrahedra(n, n, 4 * n),
                                                       GeneratedDeformation::kTwist, M_PI, 0.05);
        SimplexAssemblyOptions options;
        options.distortion = DistortionType::kIsometric;
        options.max_time_seconds = 60.0;
        const SimplexAssemblyResult r = run_simplex_assembly(mapping_problem(g), options);
        EXPECT_GT(r.initial_quality.inverted, 0) << n;
        EXPECT_TRUE(r.success) << n << ": " << r.message;
        EXPECT_EQ(r.verification.inverted + r.verification.degenerate, 0) << r.message;
        EXPECT_EQ(r.verification.branched, 0) << r.message;
        EXPECT_TRUE(r.submesh.start.iterate == StartIterate::kHandleRotations ||
                    r.submesh.start.from_handle_rotations)
            << r.submesh.start.describe();
    }
}

// A bar whose top face is pulled through its fixed bottom: far from valid after one step.
MappingProblem pulled_through_bar() {
    MappingProblem p;
    p.mesh = grid_tetrahedra(3, 3, 12);
    p.initial = p.mesh.vertices;
    const double top = p.mesh.vertices.col(2).maxCoeff();
    for (Index v = 0; v < p.mesh.num_vertices(); ++v) {
        const double z = p.mesh.vertices(v, 2);
        if (z == 0.0 || z == top) p.handles.push_back(v);
        if (z == top) p.initial(v, 2) = -1.0;
    }
    return p;
}

// A limit too short for the untangling: the run stops, the output positions are verified as
// they are, and the summary says why it stopped.
TEST(TimeLimit, StopsTheFullSolveAndTheSummarySaysSo) {
    const MappingProblem p = pulled_through_bar();
    SimplexAssemblyOptions options;
    options.mode = SolveMode::kFull;
    options.max_time_seconds = 1e-9;
    const SimplexAssemblyResult r = run_simplex_assembly(p, options);
    EXPECT_EQ(r.newton.termination, TerminationType::kMaxTime);
    EXPECT_EQ(r.newton.num_steps(), 0);  // the setup used the time: no step is started
    EXPECT_EQ(r.stages.outcome<AssemblyStop>(Stage::kAssembly), AssemblyStop::kMaxTime);
    EXPECT_EQ(r.stages.outcome<VertexStageOutcome>(Stage::kVertexStage),
              VertexStageOutcome::kSkippedTimeLimit);
    EXPECT_GT(r.verification.inverted, 0);
    EXPECT_FALSE(r.success);
    EXPECT_EQ(r.message.rfind("FAILED: ", 0), 0u) << r.message;
    EXPECT_NE(r.message.find("time limit"), std::string::npos) << r.message;
}

TEST(TimeLimit, StopsTheSubmeshStartAndItsRegions) {
    const MappingProblem p = pulled_through_bar();
    SimplexAssemblyOptions options;
    options.mode = SolveMode::kSubmesh;
    options.auto_full_tetrahedra = 100;  // a large mesh, whose start runs
    options.max_time_seconds = 1e-9;
    const SimplexAssemblyResult r = run_simplex_assembly(p, options);
    EXPECT_GT(r.initial_quality.inverted, 0);
    EXPECT_LE(r.submesh.start_iterations, 1);
    EXPECT_EQ(r.submesh.solves, 0);
    EXPECT_TRUE(r.submesh.out_of_time);
    EXPECT_GT(r.verification.inverted, 0);
    EXPECT_FALSE(r.success);
    EXPECT_NE(r.message.find("stopped at the time limit"), std::string::npos) << r.message;
}

TEST(SubmeshMode, AutoPicksFullForSmallMeshesAndSubmeshesForLargeOnes) {
    const MappingProblem small = local_folds(grid_triangles(10, 10), {5 * 11 + 5}, 0.15);
    EXPECT_EQ(run_simplex_assembly(small, SimplexAssemblyOptions{}).mode, SolveMode::kFull);
    SimplexAssemblyOptions options;
    options.auto_full_triangles = 1000;  // the 40 x 40 grid (3200 triangles) counts as large
    const MappingProblem large = local_folds(grid_triangles(40, 40), {10 * 41 + 10}, 0.06);
    EXPECT_EQ(run_simplex_assembly(large, options).mode, SolveMode::kSubmesh);
}

}  // namespace
}  // namespace sa
