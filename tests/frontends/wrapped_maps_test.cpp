// Maps wrapped twice around an interior edge, every tetrahedron positive (branch edges,
// geometry/quality/local_injectivity.h): the verification fails them and names the edge, the
// vertex stage does not start from one (its barrier would keep the wrap), and deformation posing
// of generated bars ends without one.

#include <gtest/gtest.h>

#include <cmath>

#include "frontends/deform/deform_solve.h"
#include "frontends/simplex_assembly/detail/prepared_problem.h"
#include "frontends/simplex_assembly/detail/vertex_stage.h"
#include "frontends/simplex_assembly/map_solve.h"
#include "tests/fixtures/bar_deformation.h"

namespace sa {
namespace {

constexpr int kRing = 8;

/// kRing tetrahedra around the edge from (0, 0, -1) to (0, 0, 1) and their map turning `wraps`
/// times around it, every tetrahedron positive; all vertices but the edge's ends are handles.
MappingProblem wrapped_star(int wraps) {
    MappingProblem p;
    p.source = "edge star";
    p.mesh.vertices.resize(2 + kRing, 3);
    p.mesh.vertices.row(0) << 0, 0, -1;
    p.mesh.vertices.row(1) << 0, 0, 1;
    p.mesh.simplices.resize(kRing, 4);
    p.initial = p.mesh.vertices;
    for (int k = 0; k < kRing; ++k) {
        const double a = 2.0 * M_PI * k / kRing, b = wraps * a;
        p.mesh.vertices.row(2 + k) << std::cos(a), std::sin(a), 0.0;
        p.initial.row(2 + k) << std::cos(b), std::sin(b), 0.0;
        p.mesh.simplices.row(k) << 0, 1, 2 + k, 2 + (k + 1) % kRing;
        p.handles.push_back(2 + k);
    }
    p.targets = p.initial(p.handles, Eigen::all);
    return p;
}

TEST(WrappedMaps, TheVerificationFailsAWrapAndNamesItsEdge) {
    // Every vertex fixed: nothing moves, the verification judges the initial map.
    MappingProblem p = wrapped_star(2);
    p.handles = {0, 1};
    for (int k = 0; k < kRing; ++k) p.handles.push_back(2 + k);
    p.targets = p.initial(p.handles, Eigen::all);
    const SimplexAssemblyResult r = run_simplex_assembly(p, SimplexAssemblyOptions{});
    EXPECT_FALSE(r.success);
    EXPECT_EQ(r.verification.inverted, 0);
    EXPECT_EQ(r.verification.branched, 1);
    EXPECT_EQ(r.verification.first_branch, "edge 0-1");
    EXPECT_NE(r.message.find("the first at edge 0-1"), std::string::npos) << r.message;

    p = wrapped_star(1);
    p.handles = {0, 1};
    for (int k = 0; k < kRing; ++k) p.handles.push_back(2 + k);
    p.targets = p.initial(p.handles, Eigen::all);
    EXPECT_TRUE(run_simplex_assembly(p, SimplexAssemblyOptions{}).success);
}

TEST(WrappedMaps, TheVertexStageDoesNotStartFromAWrap) {
    for (int wraps : {1, 2}) {
        const MappingProblem p = wrapped_star(wraps);
        const SimplexAssemblyOptions options;
        StageTimes times;
        const auto prepared = prepare_problem<3>(p, options, times);
        const VertexStage v = run_vertex_stage<3>(
            prepared->mesh, prepared->frames, prepared->topology, prepared->assembly.energies,
            prepared->start, vertex_stage_fixed(*prepared), options, Logger{});
        if (wraps == 1) {
            EXPECT_TRUE(v.ran()) << to_string(v.outcome);
        } else {
            EXPECT_EQ(v.outcome, VertexStageOutcome::kSkippedWrappedStart) << to_string(v.outcome);
            EXPECT_EQ(v.positions, prepared->start);
            EXPECT_NE(v.figures.find("8 simplices"), std::string::npos) << v.figures;
        }
    }
}

TEST(WrappedMaps, TheContinuationCarriesTheProblemsOwnBarrier) {
    // sa deform's problem: E_m and a volumetric barrier of its own next to the built-in E_C.
    BarDeformationOptions small;
    small.length_cells = 6;
    small.cross_cells = 2;
    small.slab = 0.2;
    const BarDeformation bar = bar_deformation(BarPose::kBend, small);
    const DeformOptions deform_options;
    const MappingProblem problem = deform_problem(bar.mesh, HandleTargets{bar.handles, bar.targets},
                                                  bar.mesh.vertices, deform_options);
    StageTimes times;
    const auto prepared = prepare_problem<3>(problem, deform_solver_options(deform_options), times);
    const ExponentContinuation<3> c = exponent_continuation<3>(*prepared);
    ASSERT_TRUE(c.energies);
    const std::vector<std::shared_ptr<const SimplexTerm<3>>> at = c.energies(0.25 * c.s);
    ASSERT_EQ(at.size(), 3u);  // E_C, E_m, the volumetric barrier
    EXPECT_EQ(at[1]->exponent(), 0.0);
    EXPECT_DOUBLE_EQ(at[2]->exponent(), 0.25 * prepared->assembly.energies[2]->exponent());
    // A tetrahedron shrunk to 1/20 of its size: conformal, but its volumetric distortion is in
    // the thousands, and that is what the continuation measures.
    const Mat<3> squashed = 0.05 * Mat<3>::Identity();
    const double volumetric = prepared->assembly.energies[2]->distortion(squashed);
    EXPECT_GT(volumetric, prepared->energy->barrier_distortion(squashed));
    EXPECT_DOUBLE_EQ(c.distortion(squashed),
                     prepared->assembly.energies[2]->exponent() / c.s * volumetric);
}

TEST(WrappedMaps, PosedBarsEndWithoutABranchEdge) {
    BarDeformationOptions options;
    options.length_cells = 12;
    options.cross_cells = 3;
    options.slab = 0.1;
    for (BarPose pose : {BarPose::kTwist, BarPose::kBendTwist}) {
        SCOPED_TRACE(to_string(pose));
        const BarDeformation bar = bar_deformation(pose, options);
        const DeformResult r = deform(bar.mesh, {bar.handles, bar.targets}, DeformOptions{});
        EXPECT_TRUE(r.success()) << r.solve.solve.message;
        EXPECT_EQ(r.solve.solve.verification.branched, 0);
    }
    // Bent by three quarters of a turn: the ARAP start folds 13 tetrahedra and untangling them
    // wraps edges (the stars are positive, the map not locally injective); such starts are not
    // taken, the regions repair the folds and the vertex stage lowers what they squashed.
    options.length_cells = 20;
    options.cross_cells = 4;
    options.slab = 0.05;
    options.bend_degrees = 270.0;
    const BarDeformation bar = bar_deformation(BarPose::kBend, options);
    const DeformResult r = deform(bar.mesh, {bar.handles, bar.targets}, DeformOptions{});
    ASSERT_TRUE(r.success()) << r.solve.solve.message;
    EXPECT_EQ(r.solve.solve.verification.branched, 0);
    EXPECT_LT(r.solve.solve.final_quality.isometric.max, 10.0);
}

}  // namespace
}  // namespace sa
