#include <gtest/gtest.h>

#include <random>

#include "frontends/simplex_assembly/map_solve.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/mesh_topology.h"
#include "optim/errors.h"

namespace sa {
namespace {

// A 2D grid whose boundary goes onto a parallelogram (a non-trivial affine target) with the
// interior scrambled: the solution is the affine map, every variant must find an inversion-free
// one.
MappingProblem sheared(int n, unsigned seed) {
    MappingProblem p;
    p.mesh = grid_triangles(n, n);
    Eigen::Matrix2d M;
    M << 2.0, 0.7, 0.1, 1.2;
    p.initial = p.mesh.vertices * M.transpose();
    const MeshTopology t = mesh_topology(p.mesh, "grid");
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    for (Index v = 0; v < p.mesh.num_vertices(); ++v) {
        if (t.boundary_vertex[v]) {
            p.handles.push_back(v);
        } else {
            p.initial.row(v) += Eigen::RowVector2d(u(rng), u(rng));
        }
    }
    return p;
}

class Variants : public ::testing::TestWithParam<Variant> {};

TEST_P(Variants, EachVariantUntangles) {
    const MappingProblem p = sheared(8, 4);
    SimplexAssemblyOptions options;
    options.variant = GetParam();
    const SimplexAssemblyResult r = run_simplex_assembly(p, options);
    EXPECT_GT(r.initial_quality.inverted, 0);
    EXPECT_TRUE(r.success) << to_string(GetParam()) << ": " << r.message;
    // The affine map is the conformal optimum: all simplices alike.
    EXPECT_NEAR(r.final_quality.conformal.max, r.final_quality.conformal.mean, 1e-3);
}

TEST_P(Variants, EachVariantAssemblesOnThePapersSchedule) {
    const MappingProblem p = sheared(8, 4);
    SimplexAssemblyOptions options;
    options.variant = GetParam();
    options.vertex_stage = false;  // lambda up to 1e16 until assembled and converged
    const SimplexAssemblyResult r = run_simplex_assembly(p, options);
    EXPECT_TRUE(r.success) << to_string(GetParam()) << ": " << r.message;
    EXPECT_TRUE(r.assembled) << r.message;
    EXPECT_LT(r.final_assembly, options.assembly_tolerance);
    EXPECT_EQ(r.stages.last(Stage::kVertexStage), nullptr);  // not asked for
    EXPECT_EQ(r.stages.outcome<AssemblyStop>(Stage::kAssembly), AssemblyStop::kAssembled);
}

INSTANTIATE_TEST_SUITE_P(AllVariants, Variants,
                         ::testing::Values(Variant::kReduced, Variant::kFull, Variant::kVertex),
                         [](const auto& info) { return std::string(1, "rfv"[int(info.param)]); });

TEST(SimplexAssembly, BoundedDistortionStaysWithinTheBound) {
    const MappingProblem p = sheared(8, 5);
    SimplexAssemblyOptions options;
    options.bound = 2.5;
    const SimplexAssemblyResult r = run_simplex_assembly(p, options);
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_TRUE(r.verification.within_bound()) << r.verification.describe();
    EXPECT_LE(r.verification.max_distortion, 2.5);
}

TEST(SimplexAssembly, WithoutHandlesOneSimplexIsAnchored) {
    MappingProblem p = sheared(6, 6);
    p.handles.clear();
    for (Index v = 0; v < p.mesh.num_vertices(); ++v)
        p.initial.row(v) = p.mesh.vertices.row(v) * 1.5;
    p.initial.row(10) += Eigen::RowVector2d(0.4, 0.1);  // a fold
    const SimplexAssemblyResult r = run_simplex_assembly(p, SimplexAssemblyOptions{});
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_GT(r.initial_quality.inverted, 0);
    EXPECT_EQ(r.num_anchored_simplices, 1);
    // Free: close to a similarity of the rest (near it E_C is flat, and the stopping test is on E).
    EXPECT_LT(r.final_quality.conformal.max, 1.05);
}

TEST(SimplexAssembly, BadInputIsRejected) {
    MappingProblem p = sheared(4, 1);
    p.handles.push_back(p.handles.front());
    EXPECT_THROW(run_simplex_assembly(p, {}), InputError);
    p = sheared(4, 1);
    p.initial.conservativeResize(p.initial.rows() - 1, Eigen::NoChange);
    EXPECT_THROW(run_simplex_assembly(p, {}), InputError);
    SimplexAssemblyOptions bad;
    bad.bound = 1.0;
    EXPECT_THROW(run_simplex_assembly(sheared(4, 1), bad), InvalidArgumentError);
}

TEST(SimplexAssembly, SameResultOnOneAndTwoThreads) {
    const MappingProblem p = sheared(10, 7);
    SimplexAssemblyOptions one, two;
    one.num_threads = 1;
    two.num_threads = 2;
    const SimplexAssemblyResult a = run_simplex_assembly(p, one), b = run_simplex_assembly(p, two);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    EXPECT_EQ(
        std::memcmp(a.positions.data(), b.positions.data(), sizeof(double) * a.positions.size()),
        0);
    EXPECT_EQ(a.newton.num_steps(), b.newton.num_steps());
}

}  // namespace
}  // namespace sa
