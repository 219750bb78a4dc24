#include "frontends/simplex_assembly/optimal_bound.h"

#include <gtest/gtest.h>

#include <cmath>

#include "frontends/simplex_assembly/detail/prepared_problem.h"
#include "geometry/mesh/mesh_generators.h"
#include "optim/errors.h"

namespace sa {
namespace {

// The unit square's grid mapped by (x + e x^2, y + e y^2 / 2): valid, and conformal K - 1 of a
// few 1e-4, the regime of a subdivided disk's LSCM map (face.obj x64: K - 1 = 3.5e-4).
MappingProblem near_conformal(int n, double e) {
    MappingProblem p;
    p.mesh = grid_triangles(n, n);
    p.initial = p.mesh.vertices.leftCols(2);
    for (Index v = 0; v < p.initial.rows(); ++v) {
        const double x = p.initial(v, 0), y = p.initial(v, 1);
        p.initial.row(v) << x + e * x * x, y + 0.5 * e * y * y;
    }
    p.reference = p.initial;
    p.source = "near-conformal grid";
    return p;
}

SimplexAssemblyOptions difference_options() {
    SimplexAssemblyOptions options;
    options.mapping_distortion = DistortionType::kDifference;
    options.mode = SolveMode::kSubmesh;
    return options;
}

OptimalBoundOptions submesh_rounds(int rounds, double tolerance) {
    OptimalBoundOptions o;
    o.rounds = rounds;
    o.tolerance = tolerance;
    o.submesh_band = 0.5;
    o.margin = 1e-6;
    return o;
}

TEST(OptimalBound, RoundsNearKOneGoOnWhileTheyLowerKMinusOne) {
    const MappingProblem p = near_conformal(16, 0.02);
    const double tolerance = 5e-3;
    const OptimalBound r = optimal_bound(p, difference_options(), submesh_rounds(12, tolerance));
    ASSERT_TRUE(r.verified) << r.solve.message;
    EXPECT_TRUE(r.solve.success && r.solve.verification.within_bound()) << r.solve.message;
    const double first = r.rounds[0].max_distortion;
    ASSERT_GT(first - 1.0, 1e-5);
    ASSERT_LT(first - 1.0, 1e-2);
    ASSERT_GE(r.rounds.size(), 3u);
    // Rounds went on whose gain was under `tolerance` of K (where a rule relative to K stopped)
    // but over `tolerance` of K - 1.
    bool past_the_old_rule = false;
    for (std::size_t k = 1; k + 1 < r.rounds.size(); ++k) {
        const double before = r.rounds[k - 1].max_distortion, after = r.rounds[k].max_distortion;
        ASSERT_TRUE(r.rounds[k].success);
        EXPECT_GT(before - after, tolerance * (before - 1.0)) << "round " << k << " went on";
        past_the_old_rule |= before - after < tolerance * before;
    }
    EXPECT_TRUE(past_the_old_rule);
    EXPECT_LT(r.solve.verification.max_distortion - 1.0, 0.8 * (first - 1.0));
    // The last round stopped them: it gained too little, or did not verify.
    if (r.rounds.size() < 12u && r.rounds.back().success) {
        const double before = r.rounds[r.rounds.size() - 2].max_distortion;
        EXPECT_LE(before - r.rounds.back().max_distortion,
                  std::max(tolerance * (before - 1.0), 1e-6 * before));
    }
}

TEST(OptimalBound, RestartedRoundsMatchRoundsPreparedAgain) {
    // The rounds keep their first round's prepared problem (restart_problem); each is the same
    // solve as a run_simplex_assembly() of the previous result with the new bound.
    const MappingProblem p = near_conformal(14, 0.05);
    const SimplexAssemblyOptions options = difference_options();
    const OptimalBoundOptions rounds = submesh_rounds(5, 0.0);
    const OptimalBound r = optimal_bound(p, options, rounds);
    ASSERT_TRUE(r.verified) << r.solve.message;
    ASSERT_GE(r.rounds.size(), 3u);
    MappingProblem fresh = p;
    SimplexAssemblyOptions o = options;
    o.submesh_band = rounds.submesh_band;
    SimplexAssemblyResult previous = run_simplex_assembly(fresh, o);
    EXPECT_DOUBLE_EQ(previous.verification.max_distortion, r.rounds[0].max_distortion);
    for (std::size_t k = 1; k < r.rounds.size(); ++k) {
        ASSERT_TRUE(r.rounds[k].success);
        fresh.initial = previous.positions;
        o.bound = previous.verification.max_distortion * (1.0 + rounds.margin);
        EXPECT_NEAR(o.bound, r.rounds[k].bound, 1e-12);
        previous = run_simplex_assembly(fresh, o);
        ASSERT_TRUE(previous.success) << previous.message;
        // The normalization keeps the first round's map centre: rounding differs, nothing else.
        EXPECT_NEAR(previous.verification.max_distortion, r.rounds[k].max_distortion, 1e-9)
            << "round " << k;
    }
}

TEST(OptimalBound, ARestartedProblemRunsTheSubmeshModeOnly) {
    MappingProblem p = near_conformal(6, 0.05);
    SimplexAssemblyOptions options = difference_options();
    StageTimes times;
    auto prepared = prepare_problem<2>(p, options, times);
    options.bound = 2.0;
    restart_problem<2>(*prepared, options, times);
    const SimplexAssemblyResult submesh = solve_prepared<2>(*prepared, options, {}, times);
    EXPECT_TRUE(submesh.success) << submesh.message;
    EXPECT_EQ(submesh.verification.bound, 2.0);
    options.mode = SolveMode::kFull;
    EXPECT_THROW(solve_prepared<2>(*prepared, options, {}, times), InvalidArgumentError);
}

}  // namespace
}  // namespace sa
