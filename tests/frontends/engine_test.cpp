#include "frontends/simplex_assembly/engine.h"

#include <gtest/gtest.h>

#include <random>

#include "energies/affine_point_energies.h"
#include "energies/distortion_barrier.h"
#include "energies/simplex_energy.h"
#include "frontends/simplex_assembly/disassembly.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/rest_frames.h"
#include "geometry/quality/map_quality.h"
#include "optim/problem_evaluation.h"
#include "tests/frontends/user_conformal.h"

namespace sa {
namespace {

// A grid with its boundary as handles and its interior scrambled, disassembled to similarities:
// the engine's input, built by hand as a front-end would (f-SA: A_s and T_s for every simplex,
// Eq. 2 per facet vertex, Eq. 3 per handle and simplex containing it).
template <int D>
struct Scrambled {
    SimplicialMesh mesh = D == 2 ? grid_triangles(8, 8) : grid_tetrahedra(4, 4, 4);
    MeshTopology topology = mesh_topology(mesh, "grid");
    RestFrames<D> frames = rest_frames<D>(mesh);
    std::vector<Mat<D>> A;
    std::vector<std::pair<Index, Vec<D>>> T;
    std::vector<Index> handles;

    explicit Scrambled(unsigned seed, Initialization start = Initialization::kClosestSimilarity) {
        Eigen::MatrixXd x = mesh.vertices.leftCols(D);
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(-0.15, 0.15);
        for (Index v = 0; v < mesh.num_vertices(); ++v) {
            if (topology.boundary_vertex[v]) {
                handles.push_back(v);
            } else {
                for (int c = 0; c < D; ++c) x(v, c) += u(rng);
            }
        }
        A = linear_parts<D>(mesh, frames, x);
        EXPECT_GT(map_quality<D>(A, frames.volume).inverted, 0) << "the start should be folded";
        project_linear_parts<D>(A, start);
        for (Index s = 0; s < mesh.num_simplices(); ++s) {
            Vec<D> centroid = Vec<D>::Zero();
            for (int k = 0; k <= D; ++k) centroid += x.row(mesh.simplices(s, k)).transpose();
            T.emplace_back(s, centroid / double(D + 1));
        }
    }

    int local(Index s, Index v) const {
        for (int k = 0; k <= D; ++k)
            if (mesh.simplices(s, k) == v) return k;
        return -1;
    }

    /// Eq. 2 and Eq. 3 on the engine, through its variable helpers.
    void add_assembly(SimplexAssemblyEngine<D>& engine) const {
        std::vector<typename AffinePointAgreementEnergy<D>::Point> points;
        std::vector<std::array<Index, 2 * (D * D + D)>> pairs;
        for (const InteriorFacet& f : topology.interior_facets) {
            const Index i = f.simplex[0], j = f.simplex[1];
            for (int k = 0; k < D; ++k) {
                const Index v = f.vertices[k];
                points.push_back({frames.corner(i, local(i, v)), frames.corner(j, local(j, v))});
                std::array<Index, 2 * (D * D + D)> e;
                const auto a = engine.affine_variables(i), b = engine.affine_variables(j);
                std::copy(a.begin(), a.end(), e.begin());
                std::copy(b.begin(), b.end(), e.begin() + a.size());
                pairs.push_back(e);
            }
        }
        engine.add_assembly_term("Eq. 2", AffinePointAgreementEnergy<D>(std::move(points)),
                                 std::move(pairs));
        std::vector<typename AffinePointTargetEnergy<D>::Target> targets;
        std::vector<std::array<Index, D * D + D>> elements;
        for (Index h : handles) {
            for (Index i = topology.vertex_begin[h]; i < topology.vertex_begin[h + 1]; ++i) {
                const Index s = topology.simplices_of_vertex[i];
                targets.push_back({frames.corner(s, local(s, h)), rest(h)});
                elements.push_back(engine.affine_variables(s));
            }
        }
        engine.add_assembly_term("Eq. 3", AffinePointTargetEnergy<D>(std::move(targets)),
                                 std::move(elements));
    }
    Vec<D> rest(Index v) const { return mesh.vertices.row(v).head(D).transpose(); }
};

template <int D>
SimplexEnergy<D> conformal_barrier(const RestFrames<D>& frames) {
    return SimplexEnergy<D>(SimplexEnergyOptions{}, frames.volume);
}

template <int D>
void expect_positive(const SimplexAssemblyEngine<D>& engine) {
    for (const Mat<D>& A : engine.linear_parts(engine.problem().variables()))
        EXPECT_GT(A.determinant(), 0.0);
}

TEST(Engine, RunsTheScheduleOfSection44In2DAnd3D) {
    for (int dim : {2, 3}) {
        auto check = [&]<int D>(std::integral_constant<int, D>) {
            const Scrambled<D> p(3);
            SimplexAssemblyEngine<D> engine(p.A, p.T);
            p.add_assembly(engine);
            engine.add_simplex_energy("E_C", conformal_barrier<D>(p.frames));
            const AssemblyEngineOptions options;
            const AssemblyRun run = engine.run(options);
            EXPECT_EQ(run.stop, AssemblyStop::kAssembled) << D << "D: " << to_string(run.stop);
            EXPECT_TRUE(run.assembled);
            EXPECT_LT(run.final_assembly, options.assembly_tolerance);
            expect_positive(engine);
            // lambda_0 = lambda_min, then lambda_k = min(lambda_min max(E_b / E~, 1), lambda_max)
            // from the previous iterate's values.
            ASSERT_GE(run.records.size(), 3u);
            EXPECT_EQ(run.records[0].lambda, options.lambda_min);
            for (std::size_t k = 1; k < run.records.size(); ++k) {
                const AssemblyRecord& prev = run.records[k - 1];
                const double expected =
                    std::min(options.lambda_min * std::max(prev.barrier / prev.assembly, 1.0),
                             options.lambda_max);
                EXPECT_EQ(run.records[k].lambda, expected) << "iteration " << k;
            }
            EXPECT_EQ(run.records.size(), std::size_t(run.newton.num_steps()) + 1);
        };
        if (dim == 2) check(std::integral_constant<int, 2>{});
        if (dim == 3) check(std::integral_constant<int, 3>{});
    }
}

TEST(Engine, AUserBarrierEqualToTheBuiltInGivesTheSameIterates) {
    const Scrambled<2> p(5);
    SimplexAssemblyEngine<2> builtin(p.A, p.T), user(p.A, p.T);
    p.add_assembly(builtin);
    p.add_assembly(user);
    builtin.add_simplex_energy("E_C", conformal_barrier<2>(p.frames));
    user.add_simplex_energy("user E_C", DistortionBarrier<2, UserConformal<2>>({}));
    const AssemblyRun a = builtin.run({}), b = user.run({});
    ASSERT_EQ(a.records.size(), b.records.size());
    for (std::size_t k = 0; k < a.records.size(); ++k) {
        EXPECT_NEAR(a.records[k].energy, b.records[k].energy, 1e-9 * a.records[k].energy) << k;
        EXPECT_NEAR(a.records[k].lambda, b.records[k].lambda, 1e-9 * a.records[k].lambda) << k;
    }
    EXPECT_LT(
        (builtin.problem().variables() - user.problem().variables()).lpNorm<Eigen::Infinity>(),
        1e-9);
}

TEST(Engine, ALinearConstraintHoldsAtTheEnd) {
    // Vertex 40 (interior) must end on the line x = 0.3 in every simplex containing it:
    // n^T (A_s u + T_s) = 0.3 with the image written by image_coefficients().
    const Scrambled<2> p(7);
    const Index v = 40;
    ASSERT_FALSE(p.topology.boundary_vertex[v]);
    SimplexAssemblyEngine<2> engine(p.A, p.T);
    p.add_assembly(engine);
    engine.add_simplex_energy("E_C", conformal_barrier<2>(p.frames));
    std::vector<LinearConstraint<6, 1>> rows;
    for (Index i = p.topology.vertex_begin[v]; i < p.topology.vertex_begin[v + 1]; ++i) {
        const Index s = p.topology.simplices_of_vertex[i];
        const auto G = engine.image_coefficients(s, p.frames.corner(s, p.local(s, v)));
        rows.push_back({engine.affine_variables(s), {G.row(0), Vec<1>(0.3)}});
    }
    const TermId constraint = engine.add_linear_constraints<6, 1>("on a line", rows);
    const AssemblyRun run = engine.run({});
    EXPECT_EQ(run.stop, AssemblyStop::kAssembled) << to_string(run.stop);
    const Eigen::VectorXd& x = engine.problem().variables();
    EXPECT_LT(engine.problem().term(constraint).value(x), 1e-12);
    for (const LinearConstraint<6, 1>& row : rows) {
        Vec<6> xe;
        for (int k = 0; k < 6; ++k) xe[k] = x[row.variables[k]];
        EXPECT_NEAR((row.rows.coefficients * xe)(0), 0.3, 1e-12);
    }
    expect_positive(engine);
}

TEST(Engine, TwoBarriersWithTheirOwnBoundsBothHold) {
    const Scrambled<2> p(9, Initialization::kClosestRotation);  // inside both bounds
    SimplexAssemblyEngine<2> engine(p.A, p.T);
    p.add_assembly(engine);
    const double conformal_bound = 3.0, volumetric_bound = 1.6;
    engine.add_simplex_energy(
        "conformal", DistortionBarrier<2, BuiltinDistortion<2>>(
                         BuiltinDistortion<2>(DistortionType::kConformal), {conformal_bound}));
    engine.add_simplex_energy(
        "volumetric", DistortionBarrier<2, BuiltinDistortion<2>>(
                          BuiltinDistortion<2>(DistortionType::kVolumetric), {volumetric_bound}));
    const AssemblyRun run = engine.run({});
    EXPECT_TRUE(run.assembled) << to_string(run.stop);
    for (const Mat<2>& A : engine.linear_parts(engine.problem().variables())) {
        const double J = A.determinant();
        ASSERT_GT(J, 0.0);
        EXPECT_LT(A.squaredNorm() / (2.0 * J), conformal_bound);
        EXPECT_LT(0.5 * (J + 1.0 / J), volumetric_bound);
    }
}

TEST(Engine, CornerLayoutNamesImagesAndLinearParts) {
    const Scrambled<3> p(2);
    std::vector<Eigen::Matrix<double, 3, 4>> corners;
    for (Index s = 0; s < p.mesh.num_simplices(); ++s)
        corners.push_back((p.A[s] * p.frames.corners[s]).colwise() + p.T[s].second);
    SimplexAssemblyEngine<3> engine =
        SimplexAssemblyEngine<3>::corner_copies(corners, p.frames.corners, p.frames.edge_inverse);
    const Eigen::VectorXd& x = engine.problem().variables();
    EXPECT_THROW(engine.linear_variables(0), InvalidArgumentError);
    for (Index s : {Index(0), Index(17)}) {
        Vec<12> xs;
        const auto vars = engine.affine_variables(s);
        for (int k = 0; k < 12; ++k) xs[k] = x[vars[k]];
        for (int k = 0; k <= 3; ++k) {
            const Vec<3> image = engine.image_coefficients(s, p.frames.corner(s, k)) * xs;
            EXPECT_LT((image - corners[s].col(k)).norm(), 1e-12);
        }
        const Vec<9> a = engine.linear_part_map(s) * xs;
        EXPECT_LT((Eigen::Map<const Mat<3>>(a.data()) - p.A[s]).norm(), 1e-12);
        EXPECT_LT((engine.linear_part(x, s) - p.A[s]).norm(), 1e-12);
        EXPECT_LT((engine.known_translations(x)[s].second - p.T[s].second).norm(), 1e-12);
    }
}

// Shared coordinates (a PolyCube plane): the top face's z is one variable. Its gradient is the sum
// of the top vertices' z-gradients without sharing, the positions read it back for every one of
// them, and a Newton run moves the face as a whole.
TEST(Engine, SharedCoordinatesAreOneVariable) {
    const SimplicialMesh mesh = grid_tetrahedra(3, 3, 3);
    const RestFrames<3> frames = rest_frames<3>(mesh);
    const Index nv = mesh.num_vertices();
    Eigen::MatrixXd start = mesh.vertices;
    std::vector<Index> top, bottom;
    for (Index v = 0; v < nv; ++v) {
        start(v, 2) *= 1.3;  // the rest shape stretched along z: the energy pulls the top down
        if (mesh.vertices(v, 2) == 1.0) top.push_back(v);
        if (mesh.vertices(v, 2) == 0.0) bottom.push_back(v);
    }
    std::vector<std::array<Index, 4>> simplices(mesh.num_simplices());
    for (Index s = 0; s < mesh.num_simplices(); ++s)
        for (int k = 0; k < 4; ++k) simplices[s][k] = mesh.simplices(s, k);
    std::vector<Index> shared(3 * nv);
    for (Index i = 0; i < 3 * nv; ++i) shared[i] = i;
    for (Index v : top) shared[3 * v + 2] = 3 * top.front() + 2;
    auto make = [&](std::vector<Index> sharing) {
        auto engine = SimplexAssemblyEngine<3>::vertex_positions(
            start, simplices, frames.corners, frames.edge_inverse, std::move(sharing));
        engine.add_simplex_energy("E_C", conformal_barrier<3>(frames));
        for (Index v : bottom) engine.fix_vertex(v);
        return engine;
    };
    SimplexAssemblyEngine<3> plain = make({}), tied = make(shared);
    const Index z = tied.vertex_variables(top.back())[2];
    EXPECT_EQ(z, 3 * top.front() + 2);
    EXPECT_EQ(tied.coordinate_variable(3 * top.back() + 2), z);
    EXPECT_LT((tied.positions(tied.problem().variables()) - start).norm(), 1e-14);

    const ProblemEvaluation e = evaluate(plain.problem(), plain.problem().variables());
    ProblemEvaluator tied_evaluator(tied.problem());
    const ProblemEvaluation f = tied_evaluator.evaluate(tied.problem().variables());
    EXPECT_NEAR(e.value, f.value, 1e-12 * std::abs(e.value));
    ProblemEvaluator plain_evaluator(plain.problem());
    const Eigen::VectorXd g = plain_evaluator.expand(e.gradient);
    double sum = 0.0;
    for (Index v : top) sum += g[3 * v + 2];
    const Eigen::VectorXd h = tied_evaluator.expand(f.gradient);
    EXPECT_NEAR(h[z], sum, 1e-10 * std::abs(sum));
    EXPECT_EQ(Index(f.gradient.size()), Index(e.gradient.size()) - Index(top.size()) + 1);

    AssemblyEngineOptions options;
    options.max_iterations = 50;
    tied.run(options);
    const Eigen::MatrixXd end = tied.positions(tied.problem().variables());
    for (Index v : top) EXPECT_EQ(end(v, 2), end(top.front(), 2));
    EXPECT_LT(end(top.front(), 2), 1.3 - 0.1);
    for (const Mat<3>& A : tied.linear_parts(tied.problem().variables()))
        EXPECT_GT(A.determinant(), 0.0);

    shared[3 * top.front() + 2] = 0;  // a chain: the coordinate it names shares another's
    EXPECT_THROW(make(shared), InvalidArgumentError);
}

TEST(Engine, SaysWhyItStopped) {
    const Scrambled<2> p(4);
    {
        SimplexAssemblyEngine<2> engine(p.A, p.T);
        p.add_assembly(engine);
        engine.add_simplex_energy("E_C", conformal_barrier<2>(p.frames));
        AssemblyEngineOptions options;
        options.max_iterations = 1;
        EXPECT_EQ(engine.run(options).stop, AssemblyStop::kMaxIterations);
    }
    {
        SimplexAssemblyEngine<2> engine(p.A, p.T);
        p.add_assembly(engine);
        engine.add_simplex_energy("E_C", conformal_barrier<2>(p.frames));
        AssemblyHooks hooks;
        hooks.after_iteration = [](const AssemblyRecord& r, const Eigen::VectorXd&) {
            return r.iteration == 2;
        };
        const AssemblyRun run = engine.run({}, hooks);
        EXPECT_EQ(run.stop, AssemblyStop::kHook);
        EXPECT_EQ(run.newton.num_steps(), 2);
    }
    {
        std::vector<Mat<2>> inverted = p.A;
        inverted[3].col(0) *= -1.0;
        SimplexAssemblyEngine<2> engine(inverted, p.T);
        p.add_assembly(engine);
        engine.add_simplex_energy("E_C", conformal_barrier<2>(p.frames));
        EXPECT_EQ(engine.run({}).stop, AssemblyStop::kInfeasibleStart);
    }
    {
        SimplexAssemblyEngine<2> engine(p.A, p.T);
        p.add_assembly(engine);
        for (Index s = 0; s < engine.num_simplices(); ++s) engine.fix_simplex(s);
        EXPECT_EQ(engine.run({}).stop, AssemblyStop::kNoFreeVariables);
    }
    SimplexAssemblyEngine<2> reduced(p.A, {p.T[0]});
    EXPECT_TRUE(reduced.has_translation(0));
    EXPECT_FALSE(reduced.has_translation(1));
    EXPECT_THROW(reduced.translation_variables(1), InvalidArgumentError);
    EXPECT_THROW(reduced.affine_variables(1), InvalidArgumentError);
    EXPECT_THROW(reduced.linear_variables(-1), InvalidArgumentError);
    AssemblyEngineOptions bad;
    bad.lambda_max = 1.0;
    EXPECT_THROW(reduced.run(bad), InvalidArgumentError);
}

}  // namespace
}  // namespace sa
