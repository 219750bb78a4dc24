// The mesh driver with a user's own per-simplex energies and linear constraints: in the full
// mode, the submesh mode, the vertex stage, each variant, and in verification.
#include <gtest/gtest.h>

#include <random>

#include "energies/distortion_barrier.h"
#include "frontends/simplex_assembly/map_solve.h"
#include "frontends/simplex_assembly/optimal_bound.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/mesh_topology.h"
#include "optim/errors.h"
#include "tests/frontends/scrambled_problem.h"
#include "tests/frontends/user_conformal.h"

namespace sa {
namespace {

template <int D>
std::shared_ptr<const SimplexTerm<D>> volumetric_barrier(double bound) {
    return simplex_term<D>("volumetric",
                           DistortionBarrier<D, BuiltinDistortion<D>>(
                               BuiltinDistortion<D>(DistortionType::kVolumetric), {bound}));
}

TEST(UserTerms, AUserBarrierEqualToTheBuiltInGivesTheSameIteratesInEveryVariant) {
    for (Variant variant : {Variant::kReduced, Variant::kFull, Variant::kVertex}) {
        const MappingProblem builtin = scrambled(grid_triangles(8, 8), 0.12, 2);
        MappingProblem user = builtin;
        user.energies.push_back(
            simplex_term<2>("user conformal", DistortionBarrier<2, UserConformal<2>>({})));
        SimplexAssemblyOptions options, without;
        options.variant = without.variant = variant;
        without.builtin_energy = false;
        const SimplexAssemblyResult a = run_simplex_assembly(builtin, options);
        const SimplexAssemblyResult b = run_simplex_assembly(user, without);
        ASSERT_TRUE(a.success && b.success) << a.message << " / " << b.message;
        EXPECT_EQ(a.newton.num_steps(), b.newton.num_steps()) << to_string(variant);
        EXPECT_EQ(a.vertex_stage.num_steps(), b.vertex_stage.num_steps()) << to_string(variant);
        EXPECT_LT((a.positions - b.positions).cwiseAbs().maxCoeff(), 1e-8) << to_string(variant);
    }
}

TEST(UserTerms, TwoBarriersWithTwoBoundsBothHold) {
    MappingProblem p = scrambled(grid_tetrahedra(4, 4, 4), 0.12, 5);
    p.energies.push_back(volumetric_barrier<3>(1.3));
    SimplexAssemblyOptions options;
    options.bound = 1.6;                                        // the built-in conformal barrier's
    options.initialization = Initialization::kClosestRotation;  // inside both bounds
    const SimplexAssemblyResult r = run_simplex_assembly(p, options);
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_TRUE(r.verification.within_bound()) << r.verification.describe();
    ASSERT_EQ(r.verification.bounds.size(), 1u);
    EXPECT_EQ(r.verification.bounds[0].name, "volumetric");
    EXPECT_LT(r.verification.bounds[0].max_distortion, 1.3);
    EXPECT_LT(r.verification.max_distortion, 1.6);
    EXPECT_GT(r.initial_quality.inverted, 0);
}

TEST(UserTerms, AUserBoundIsVerifiedOnTheOutput) {
    // A bound the map cannot meet: the handles stretch the square to twice its area.
    MappingProblem p = scrambled(grid_triangles(6, 6), 0.0, 1);
    p.initial *= std::sqrt(2.0);
    p.energies.push_back(volumetric_barrier<2>(1.1));  // det within (0.64, 1.56)
    SimplexAssemblyOptions options;
    options.initialization = Initialization::kClosestRotation;
    const SimplexAssemblyResult r = run_simplex_assembly(p, options);
    ASSERT_EQ(r.verification.bounds.size(), 1u);
    EXPECT_GT(r.verification.bounds[0].max_distortion, 1.1);
    EXPECT_FALSE(r.verification.within_bound()) << r.verification.describe();
}

TEST(UserTerms, TheOptimalBoundLowersTwoBoundsAtOnce) {
    // The handles stretch the square by 1.3 along x: both distortions are above 1 at the optimum.
    MappingProblem p = scrambled(grid_triangles(8, 8), 0.1, 3);
    p.initial.col(0) *= 1.3;
    p.energies.push_back(volumetric_barrier<2>(3.0));
    SimplexAssemblyOptions options;
    options.bound = 3.0;
    options.initialization = Initialization::kClosestRotation;
    OptimalBoundOptions rounds;
    rounds.rounds = 4;
    rounds.tolerance = 1e-3;
    const OptimalBound r = optimal_bound(p, options, rounds);
    ASSERT_TRUE(r.verified);
    EXPECT_TRUE(r.solve.success && r.solve.verification.within_bound()) << r.solve.message;
    ASSERT_GE(r.rounds.size(), 2u);
    EXPECT_GT(r.initial_quality.inverted, 0);
    for (std::size_t k = 1; k < r.rounds.size(); ++k) {
        // Each round's two bounds are the previous round's two largest distortions.
        ASSERT_TRUE(r.rounds[k - 1].success);
        ASSERT_EQ(r.rounds[k].bounds.size(), 1u);
        EXPECT_EQ(r.rounds[k].bound, r.rounds[k - 1].max_distortion);
        EXPECT_EQ(r.rounds[k].bounds[0].bound, r.rounds[k - 1].bounds[0].max_distortion);
        if (r.rounds[k].success) {
            EXPECT_LE(r.rounds[k].max_distortion, r.rounds[k].bound);
            EXPECT_LE(r.rounds[k].bounds[0].max_distortion, r.rounds[k].bounds[0].bound);
        }
    }
    EXPECT_LT(r.solve.verification.bounds[0].max_distortion, r.rounds[0].bounds[0].bound);
}

// Vertices of the bottom row slide on y = 0 (one of them a handle), the top row is pushed down
// through the rows below it.
MappingProblem sliding_bottom(const SimplicialMesh& mesh) {
    MappingProblem p;
    p.mesh = mesh;
    p.initial = mesh.vertices;
    const int d = mesh.simplex_dimension();
    const Index up = d == 2 ? 1 : 2;
    p.handles.push_back(0);
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        if (mesh.vertices(v, up) == 1.0) {
            p.handles.push_back(v);
            p.initial(v, 0) += 0.3;
            p.initial(v, up) -= 0.4;
        }
    }
    Eigen::VectorXd normal = Eigen::VectorXd::Zero(d);
    normal[up] = 2.0;  // not a unit vector: the driver normalizes
    for (const auto& [a, b] : mesh_topology(mesh, "grid").edges) {
        if (mesh.vertices(a, up) == 0.0 && mesh.vertices(b, up) == 0.0)
            p.constraints.push_back({a, b, normal, 0.0});
    }
    return p;
}

double largest_off_plane(const MappingProblem& p, const Eigen::MatrixXd& positions) {
    const Index up = p.mesh.simplex_dimension() == 2 ? 1 : 2;
    double off = 0.0;
    for (Index v = 0; v < p.mesh.num_vertices(); ++v)
        if (p.mesh.vertices(v, up) == 0.0) off = std::max(off, std::abs(positions(v, up)));
    return off;
}

TEST(UserTerms, ALinearConstraintHoldsTo1e12InEveryVariantAndDimension) {
    for (const SimplicialMesh& mesh : {grid_triangles(8, 8), grid_tetrahedra(3, 3, 3)}) {
        for (Variant variant : {Variant::kReduced, Variant::kFull, Variant::kVertex}) {
            const MappingProblem p = sliding_bottom(mesh);
            SimplexAssemblyOptions options;
            options.variant = variant;
            const SimplexAssemblyResult r = run_simplex_assembly(p, options);
            const std::string what =
                std::to_string(mesh.simplex_dimension()) + "D " + to_string(variant);
            EXPECT_GT(r.initial_quality.inverted, 0) << what;
            EXPECT_TRUE(r.success) << what << ": " << r.message;
            EXPECT_LE(largest_off_plane(p, r.positions), 1e-12) << what;
            EXPECT_EQ(r.verification.constraints, Index(p.constraints.size()));
            EXPECT_LE(r.verification.constraint_error, 1e-12) << what;
        }
    }
}

TEST(UserTerms, AViolatedConstraintFailsVerification) {
    MappingProblem p = sliding_bottom(grid_triangles(6, 6));
    // The bottom row's two corners are handles: the rows along it must add up to 0, and one
    // asks for 0.1.
    for (Index v = 0; v < p.mesh.num_vertices(); ++v)
        if (p.mesh.vertices(v, 0) == 1.0 && p.mesh.vertices(v, 1) == 0.0) p.handles.push_back(v);
    p.constraints.front().value = 0.2;
    SimplexAssemblyOptions options;
    options.max_iterations = 30;
    const SimplexAssemblyResult r = run_simplex_assembly(p, options);
    EXPECT_GT(r.verification.constraint_error, r.verification.constraint_tolerance);
    EXPECT_FALSE(r.success) << r.message;
}

TEST(UserTerms, SubmeshRegionsGetTheUsersEnergies) {
    // Local folds in a large grid: the submesh mode solves regions around them, each with the
    // user's barrier restricted to it; row 20, away from the folds, keeps its y by constraints
    // that the regions do not touch.
    MappingProblem p = scrambled(grid_triangles(40, 40), 0.0, 1);
    const Eigen::MatrixXd rest = p.initial;
    for (Index v : {Index(10 * 41 + 10), Index(30 * 41 + 25), Index(12 * 41 + 33)})
        p.initial(v, 0) += 0.06;
    p.energies.push_back(volumetric_barrier<2>(2.0));
    for (const auto& [a, b] : mesh_topology(p.mesh, "grid").edges) {
        if (a / 41 == 20 && b / 41 == 20)
            p.constraints.push_back({a, b, Eigen::Vector2d(0.0, 1.0), 0.0});
    }
    SimplexAssemblyOptions options;
    options.mode = SolveMode::kSubmesh;
    options.rings = 2;
    options.start_iterations = 0;
    options.initialization = Initialization::kClosestRotation;
    const SimplexAssemblyResult r = run_simplex_assembly(p, options);
    EXPECT_EQ(r.mode, SolveMode::kSubmesh);
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_TRUE(r.verification.within_bound()) << r.verification.describe();
    ASSERT_EQ(r.verification.bounds.size(), 1u);
    EXPECT_LE(r.verification.constraint_error, 1e-12);
    ASSERT_FALSE(r.submesh.rounds.empty());
    EXPECT_LT(r.submesh.largest_submesh, p.mesh.num_simplices() / 4);
}

TEST(UserTerms, BadInputIsRejected) {
    MappingProblem p = scrambled(grid_triangles(4, 4), 0.1, 1);
    p.energies.push_back(volumetric_barrier<3>(2.0));  // a 3D energy on triangles
    EXPECT_THROW(run_simplex_assembly(p, {}), InvalidArgumentError);
    p.energies.clear();
    SimplexAssemblyOptions none;
    none.builtin_energy = false;  // and no energy of the user's: no barrier at all
    EXPECT_THROW(run_simplex_assembly(p, none), InvalidArgumentError);
    p.constraints.push_back({0, 24, Eigen::Vector2d(0.0, 1.0), 0.0});  // not an edge
    EXPECT_THROW(run_simplex_assembly(p, {}), InputError);
    p.constraints.back() = {0, 1, Eigen::Vector2d(0.0, 0.0), 0.0};  // no normal
    EXPECT_THROW(run_simplex_assembly(p, {}), InputError);
    p.constraints.back() = {0, 1, Eigen::Vector3d(0.0, 0.0, 1.0), 0.0};  // a 3D normal
    EXPECT_THROW(run_simplex_assembly(p, {}), InputError);
}

}  // namespace
}  // namespace sa
