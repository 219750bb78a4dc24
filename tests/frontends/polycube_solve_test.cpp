// The PolyCube solve (frontends/polycube/polycube_solve.h) and the driver's plugin hook
// (frontends/simplex_assembly/assembly_plugin.h) it stands on, on generated voxel shapes.
#include "frontends/polycube/polycube_solve.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <string>
#include <vector>

#include "frontends/polycube/cube_cover.h"
#include "frontends/polycube/polycube_planes.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/rest_frames.h"
#include "geometry/quality/map_quality.h"
#include "optim/errors.h"
#include "tests/fixtures/polycube_fixtures.h"

namespace sa {
namespace {

/// A user's plugin: the vertices of the top face (rest z = 1) of a unit cube stay on one plane
/// z = c. Assembly stage: e_z^T A_t e = 0 on two edges of each top facet's tetrahedron; vertex
/// stage: the top vertices projected onto their mean z, which they keep (the variable is fixed).
class TopOnPlane final : public AssemblyPlugin<3> {
  public:
    explicit TopOnPlane(const SimplicialMesh& mesh) : AssemblyPlugin<3>("top on a plane") {
        for (Index v = 0; v < mesh.num_vertices(); ++v)
            if (mesh.vertices(v, 2) > 1.0 - 1e-12) top_.push_back(v);
        for (Index t = 0; t < mesh.num_simplices(); ++t) {
            std::vector<int> corners;
            for (int k = 0; k < 4; ++k)
                if (mesh.vertices(mesh.simplices(t, k), 2) > 1.0 - 1e-12) corners.push_back(k);
            if (corners.size() == 3) facets_.push_back({t, corners[0], corners[1], corners[2]});
        }
    }
    void add_assembly_terms(SimplexAssemblyEngine<3>& engine,
                            const PluginStage<3>& stage) const override {
        ++assembly_calls;
        std::vector<LinearPartConstraint<3, 1>> rows;
        for (const auto& f : facets_) {
            for (int k = 2; k <= 3; ++k) {
                const Vec<3> e =
                    stage.frames->corner(f[0], f[k]) - stage.frames->corner(f[0], f[1]);
                LinearPartConstraint<3, 1> row;
                row.simplex = f[0];
                row.rows.coefficients.setZero();
                // z^T A e = sum_j A_2j e_j; vec(A) column-major: A_2j at 2 + 3 j.
                for (int j = 0; j < 3; ++j) row.rows.coefficients(0, 2 + 3 * j) = e[j] / e.norm();
                row.rows.rhs[0] = 0.0;
                rows.push_back(row);
            }
        }
        engine.add_linear_part_constraints<1>("top planarity", rows);
    }
    bool project(Eigen::MatrixXd& positions, const PluginStage<3>&) const override {
        double z = 0.0;
        for (Index v : top_) z += positions(v, 2);
        z /= double(top_.size());
        for (Index v : top_) positions(v, 2) = z;
        return true;
    }
    void add_vertex_terms(SimplexAssemblyEngine<3>& engine, const PluginStage<3>&) const override {
        ++vertex_calls;
        for (Index v : top_) engine.problem().set_fixed(engine.vertex_variables(v)[2]);
    }
    const std::vector<Index>& top() const { return top_; }
    mutable std::atomic<int> assembly_calls{0}, vertex_calls{0};

  private:
    std::vector<Index> top_;
    std::vector<std::array<Index, 4>> facets_;  ///< tet, then its three top corners
};

Eigen::Matrix3d rotation(double angle, const Eigen::Vector3d& axis) {
    return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

TEST(PolycubeSolve, TheDriverCallsAPluginInEveryStageAndItsConstraintHoldsExactly) {
    MappingProblem p;
    p.mesh = grid_tetrahedra(3, 3, 3);
    // A rotated and squeezed start: the top is neither flat nor horizontal.
    const Eigen::Matrix3d R = rotation(0.4, {1.0, 2.0, 0.5});
    p.initial = p.mesh.vertices * R.transpose();
    for (Index v = 0; v < p.mesh.num_vertices(); ++v)
        p.initial(v, 0) += 0.1 * std::sin(3.0 * p.mesh.vertices(v, 2));
    auto plugin = std::make_shared<TopOnPlane>(p.mesh);
    ASSERT_EQ(plugin->top().size(), 16u);
    p.plugins.push_back(plugin);
    const SimplexAssemblyResult r = run_simplex_assembly(p, SimplexAssemblyOptions{});
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_EQ(r.stages.outcome<VertexStageOutcome>(Stage::kVertexStage), VertexStageOutcome::kRan)
        << r.message;
    EXPECT_EQ(plugin->assembly_calls.load(), 1);
    EXPECT_GE(plugin->vertex_calls.load(), 1);
    double lo = kInfinity, hi = -kInfinity;
    for (Index v : plugin->top()) {
        lo = std::min(lo, r.positions(v, 2));
        hi = std::max(hi, r.positions(v, 2));
    }
    EXPECT_LE(hi - lo, 1e-12);

    // The submesh mode cannot restrict a plugin's terms: refused, naming the plugin.
    SimplexAssemblyOptions submesh;
    submesh.mode = SolveMode::kSubmesh;
    try {
        run_simplex_assembly(p, submesh);
        FAIL() << "the submesh mode accepted a plugin";
    } catch (const InvalidArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("top on a plane"), std::string::npos) << e.what();
    }
    // The descent mode runs the vertex stage alone, which projects its start onto the plugin's
    // plane and calls the plugin there.
    SimplexAssemblyOptions descent;
    descent.mode = SolveMode::kDescent;
    const int vertex_calls = plugin->vertex_calls.load();
    MappingProblem valid = p;
    valid.initial = p.mesh.vertices;
    const SimplexAssemblyResult d = run_simplex_assembly(valid, descent);
    EXPECT_EQ(d.mode, SolveMode::kDescent);
    EXPECT_TRUE(d.success) << d.message;
    EXPECT_GT(plugin->vertex_calls.load(), vertex_calls);
    // A plugin of the wrong dimension is rejected.
    MappingProblem flat;
    flat.mesh = grid_triangles(2, 2);
    flat.initial = flat.mesh.vertices;
    flat.plugins.push_back(plugin);
    EXPECT_THROW(run_simplex_assembly(flat, SimplexAssemblyOptions{}), InvalidArgumentError);
}

PreparedPolycube prepared_shape(const SimplicialMesh& mesh) {
    return prepare_polycube(mesh, "generated", PolycubeLabelInput{});
}

// Planarity holds exactly (1e-9 of the diagonal, measured by verify_polycube) from a start that
// is rotated away from the axes and folded: no chart is planar or axis-aligned in it.
TEST(PolycubeSolve, ChartsArePlanarFromARotatedFoldedStart) {
    const PreparedPolycube prepared =
        prepared_shape(testing::bent(testing::voxel_tetrahedra(testing::l_shape(), 2), 0.08));
    MappingProblem p;
    p.mesh = prepared.mesh;
    const Eigen::Matrix3d R = rotation(0.5, {0.3, -1.0, 0.7});
    p.initial = prepared.mesh.vertices * R.transpose();
    // Fold: push one vertex of the interior through its neighbours.
    Index inner = -1;
    for (Index v = 0; v < prepared.mesh.num_vertices() && inner < 0; ++v)
        if (!prepared.boundary.on_boundary[v]) inner = v;
    ASSERT_GE(inner, 0);
    p.initial.row(inner) += Eigen::RowVector3d(0.9, 0.0, 0.0);
    const RestFrames<3> frames = rest_frames<3>(prepared.mesh);
    const MapQuality start =
        map_quality<3>(linear_parts<3>(prepared.mesh, frames, p.initial), frames.volume);
    ASSERT_GT(start.inverted, 0);
    const PolycubeVerification before =
        verify_polycube(prepared.layout(), p.initial, prepared.input_volume);
    ASSERT_FALSE(before.passed);
    ASSERT_GT(before.nonplanar_charts, 0);
    p.plugins.push_back(polycube_plugin(prepared));
    SimplexAssemblyOptions options;
    options.untangle_fallback = false;
    const SimplexAssemblyResult r = run_simplex_assembly(p, options);
    ASSERT_TRUE(r.success) << r.message;
    const PolycubeVerification v =
        verify_polycube(prepared.layout(), r.positions, prepared.input_volume);
    EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
    EXPECT_EQ(v.nonplanar_charts, 0);
    EXPECT_LE(v.max_planarity, 1e-9);
    EXPECT_EQ(v.wrong_side_charts, 0);
}

TEST(PolycubeSolve, SolveFromTheCubeCoverIsVerifiedWithAndWithoutTheOptimalBound) {
    const PreparedPolycube prepared =
        prepared_shape(testing::bent(testing::voxel_tetrahedra(testing::l_shape(), 2), 0.15));
    const PolycubeSolve plain = solve_polycube(prepared, {});
    ASSERT_TRUE(plain.success) << plain.message;
    EXPECT_TRUE(plain.verification.passed);
    EXPECT_EQ(plain.verification.quality.inverted, 0);
    PolycubeSolveOptions rounds;
    rounds.optimal_bound = true;
    rounds.rounds = 3;
    const PolycubeSolve bounded = solve_polycube(prepared, rounds);
    ASSERT_TRUE(bounded.success) << bounded.message;
    ASSERT_FALSE(bounded.rounds.empty());
    EXPECT_LE(bounded.verification.quality.conformal.max,
              plain.verification.quality.conformal.max * (1.0 + 1e-9));
    PolycubeSolveOptions both;
    both.bound = 3.0;
    both.optimal_bound = true;
    EXPECT_THROW(solve_polycube(prepared, both), InvalidArgumentError);
}

// The L-shaped block unbent is its own PolyCube: the first round's map is exact (conformal
// distortion 1, the least there is), no bound can be below it, and the rounds end there with the
// map verified instead of asking for a bound of 1.
TEST(PolycubeSolve, AnExactMapEndsTheOptimalBoundRounds) {
    const PreparedPolycube prepared =
        prepared_shape(testing::voxel_tetrahedra(testing::l_shape(), 2));
    PolycubeSolveOptions rounds;
    rounds.optimal_bound = true;
    rounds.rounds = 3;
    const PolycubeSolve exact = solve_polycube(prepared, rounds);
    ASSERT_TRUE(exact.success) << exact.message;
    EXPECT_LE(exact.verification.quality.conformal.max, 1.0 + 1e-9);
    EXPECT_EQ(exact.rounds.size(), 1u);
}

// A box whose top and bottom centres are in many tetrahedra (48 before the splits): every
// boundary vertex and edge has its angle barrier (the log counts them and their largest stars),
// and the map is verified (the angle sums measured at every vertex).
TEST(PolycubeSolve, VerticesWithManyNeighboursAreSolved) {
    const PreparedPolycube prepared = prepared_shape(testing::fan_box(12));
    ASSERT_EQ(prepared.charts.size(), 6);
    std::vector<std::string> lines;
    const PolycubeSolve solve =
        solve_polycube(prepared, {}, [&](const std::string& line) { lines.push_back(line); });
    ASSERT_TRUE(solve.success) << solve.message;
    EXPECT_EQ(solve.verification.vertex_angle_violations, 0);
    const std::string expected = "polycube: angle barriers on " +
                                 std::to_string(prepared.fans.size()) + " boundary edges (up to ";
    std::size_t largest = 0;
    for (const BoundaryVertexStar& star : prepared.stars)
        largest = std::max(largest, star.tets.size());
    EXPECT_GT(largest, 14u);
    const std::string vertices = " and " + std::to_string(prepared.stars.size()) +
                                 " boundary vertices (up to " + std::to_string(largest) +
                                 " tetrahedra)";
    const auto line = std::find_if(lines.begin(), lines.end(),
                                   [&](const std::string& l) { return l.rfind(expected, 0) == 0; });
    ASSERT_NE(line, lines.end());
    EXPECT_NE(line->find(vertices), std::string::npos) << *line;
}

/// The stage in which the driver calls the plugin's projection with the mesh at hand.
PluginStage<3> vertex_stage(const PreparedPolycube& prepared, const RestFrames<3>& frames) {
    PluginStage<3> stage;
    stage.kind = PluginStage<3>::Kind::kVertex;
    stage.mesh = &prepared.mesh;
    stage.frames = &frames;
    return stage;
}

// The assembly terms hold the map's scale (f-SA): at a PolyCube (the cube cover) E~ is 0, and
// the same map shrunk to half its size, still planar, is no longer assembled, because each
// boundary vertex is held on its plane at the start's offset. Planarity alone (on A) would give
// the shrunk map E~ = 0 as well, and the assembly shrank cup's map (docs/measurements.md,
// PolyCube).
// Planes held where given (the quantized PolyCube of a hex mesh): from a verified map scaled by
// 1.5 with every plane held at 1.5 times its coordinate plus 0.25 on one plane of x, the solve
// ends verified with each plane's vertices exactly there; an inversion-free start goes to the
// vertex stage alone.
TEST(PolycubeSolve, PlanesHeldWhereGivenStayThere) {
    const PreparedPolycube prepared =
        prepared_shape(testing::bent(testing::voxel_tetrahedra(testing::l_shape(), 2), 0.1));
    const PolycubeSolve free = solve_polycube(prepared, {});
    ASSERT_TRUE(free.success) << free.message;
    const PolycubePlanes planes =
        polycube_planes(prepared.boundary, prepared.charts, prepared.mesh.num_vertices());
    std::vector<double> held(planes.size(), 0.0);
    for (Index v = 0; v < prepared.mesh.num_vertices(); ++v)
        for (int a = 0; a < 3; ++a)
            if (planes.plane_of_vertex[v][a] >= 0)
                held[planes.plane_of_vertex[v][a]] = 1.5 * free.positions(v, a);
    // The x plane in the middle of the L moves by a sixth of the arm's width.
    int middle = -1;
    for (int p = 0; p < planes.size(); ++p) {
        if (planes.axis[p] != 0) continue;
        int below = 0, above = 0;
        for (int q = 0; q < planes.size(); ++q) {
            if (planes.axis[q] != 0 || q == p) continue;
            (held[q] < held[p] ? below : above) += 1;
        }
        if (below > 0 && above > 0) middle = p;
    }
    ASSERT_GE(middle, 0);
    held[middle] += 0.25;
    const PolycubeSolve r = solve_polycube_on_planes(prepared, free.positions * 1.5, held, {});
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_EQ(r.solve.mode, SolveMode::kDescent);
    for (Index v = 0; v < prepared.mesh.num_vertices(); ++v)
        for (int a = 0; a < 3; ++a)
            if (planes.plane_of_vertex[v][a] >= 0)
                EXPECT_NEAR(r.positions(v, a), held[planes.plane_of_vertex[v][a]], 1e-12);
    EXPECT_THROW(solve_polycube_on_planes(prepared, free.positions, {1.0}, {}),
                 InvalidArgumentError);
    EXPECT_THROW(solve_polycube_on_planes(prepared, free.positions, {}, {}), InvalidArgumentError);
}

TEST(PolycubeSolve, TheAssemblyHoldsThePlanesAtTheStartOffsets) {
    const PreparedPolycube prepared =
        prepared_shape(testing::bent(testing::voxel_tetrahedra(testing::l_shape(), 2), 0.15));
    const CubeCover cover = cube_cover_map(prepared.mesh, prepared.boundary, prepared.charts);
    const RestFrames<3> frames = rest_frames<3>(prepared.mesh);
    const std::vector<Mat<3>> A = linear_parts<3>(prepared.mesh, frames, cover.positions);
    std::vector<std::pair<Index, Vec<3>>> translations;
    for (Index t = 0; t < prepared.mesh.num_simplices(); ++t) {
        const Vec<3> x0 = cover.positions.row(prepared.mesh.simplices(t, 0)).transpose();
        translations.emplace_back(t, x0 - A[t] * frames.corner(t, 0));
    }
    auto assembly_energy = [&](double shrink, bool translations_everywhere) {
        SimplexAssemblyEngine<3> engine(
            A, translations_everywhere ? translations : std::vector<std::pair<Index, Vec<3>>>{});
        PluginStage<3> stage;
        stage.mesh = &prepared.mesh;
        stage.frames = &frames;
        polycube_plugin(prepared)->add_assembly_terms(engine, stage);
        engine.problem().set_variables(shrink * engine.problem().variables());
        return engine.assembly_energy();
    };
    EXPECT_LT(assembly_energy(1.0, true), 1e-12);
    EXPECT_GT(assembly_energy(0.5, true), 1e-3);
    // Without translations (r-SA) only planarity is there: the shrunk map stays assembled.
    EXPECT_LT(assembly_energy(0.5, false), 1e-12);
}

// The plugin's projection untangles what flattening folds (PolycubePluginOptions): a valid
// PolyCube (the cube cover of the shape) with interior vertices pushed through their neighbours
// comes back inversion-free, every plane's coordinate where it was, and passes verify_polycube
// (planar charts, every angle sum below its limit).
TEST(PolycubeSolve, TheProjectionUntanglesOnThePlanes) {
    const PreparedPolycube prepared =
        prepared_shape(testing::bent(testing::voxel_tetrahedra(testing::l_shape(), 2), 0.15));
    const CubeCover cover = cube_cover_map(prepared.mesh, prepared.boundary, prepared.charts);
    ASSERT_TRUE(verify_polycube(prepared.layout(), cover.positions, prepared.input_volume).passed);
    const RestFrames<3> frames = rest_frames<3>(prepared.mesh);
    Eigen::MatrixXd folded = cover.positions;
    int pushed = 0;
    for (Index v = 0; v < prepared.mesh.num_vertices() && pushed < 3; ++v) {
        if (prepared.boundary.on_boundary[v]) continue;
        folded.row(v) += Eigen::RowVector3d(0.6, -0.4, 0.3);
        ++pushed;
    }
    ASSERT_GT(
        map_quality<3>(linear_parts<3>(prepared.mesh, frames, folded), frames.volume).inverted, 0);
    const PluginStage<3> stage = vertex_stage(prepared, frames);
    Eigen::MatrixXd projected = folded;
    ASSERT_TRUE(polycube_plugin(prepared)->project(projected, stage));
    const PolycubeVerification v =
        verify_polycube(prepared.layout(), projected, prepared.input_volume);
    EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
    EXPECT_EQ(v.quality.inverted + v.quality.degenerate, 0);
    EXPECT_EQ(v.edge_angle_violations + v.vertex_angle_violations, 0);
    // The planes move as wholes: every chart keeps one coordinate along its axis, and the
    // outermost planes of each axis (held, so that the map cannot shrink) keep theirs.
    for (int c = 0; c < prepared.charts.size(); ++c) {
        const int axis = label_axis(prepared.charts.label[c]);
        const double at =
            projected(prepared.boundary.triangles(prepared.charts.members[c][0], 0), axis);
        for (const Index b : prepared.charts.members[c])
            for (int i = 0; i < 3; ++i)
                EXPECT_EQ(projected(prepared.boundary.triangles(b, i), axis), at) << "chart " << c;
    }
    for (int axis = 0; axis < 3; ++axis) {
        for (const bool top : {false, true}) {
            Index outer = -1;
            for (Index b = 0; b < prepared.boundary.size(); ++b) {
                if (label_axis(prepared.labels[b]) != axis) continue;
                const Index u = prepared.boundary.triangles(b, 0);
                if (outer < 0 || (top ? folded(u, axis) > folded(outer, axis)
                                      : folded(u, axis) < folded(outer, axis)))
                    outer = u;
            }
            EXPECT_NEAR(projected(outer, axis), folded(outer, axis), 1e-12);
        }
    }
    // Without untangling the projection leaves the fold for the driver to refuse.
    PolycubePluginOptions off;
    off.untangle_iterations = 0;
    Eigen::MatrixXd kept = folded;
    ASSERT_TRUE(polycube_plugin(prepared, 1.0, off)->project(kept, stage));
    EXPECT_LE((kept - folded).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_GT(map_quality<3>(linear_parts<3>(prepared.mesh, frames, kept), frames.volume).inverted,
              0);
}

// A fold is untangled where it is: a bar of eight cubes folded at one end comes back a verified
// PolyCube with the vertices of its other half where they were (the whole mesh would move them:
// the untangling runs to convergence).
TEST(PolycubeSolve, TheProjectionUntanglesAFoldLocally) {
    std::vector<testing::Cell> bar;
    for (int x = 0; x < 8; ++x) bar.push_back({x, 0, 0});
    const PreparedPolycube prepared = prepared_shape(testing::voxel_tetrahedra(bar, 2));
    const CubeCover cover = cube_cover_map(prepared.mesh, prepared.boundary, prepared.charts);
    ASSERT_TRUE(verify_polycube(prepared.layout(), cover.positions, prepared.input_volume).passed);
    const RestFrames<3> frames = rest_frames<3>(prepared.mesh);
    Eigen::MatrixXd folded = cover.positions;
    Index inner = -1;
    for (Index v = 0; v < prepared.mesh.num_vertices() && inner < 0; ++v) {
        if (!prepared.boundary.on_boundary[v] && prepared.mesh.vertices(v, 0) == 0.5) inner = v;
    }
    ASSERT_GE(inner, 0);
    folded.row(inner) += Eigen::RowVector3d(0.7, 0.1, 0.0);
    ASSERT_GT(
        map_quality<3>(linear_parts<3>(prepared.mesh, frames, folded), frames.volume).inverted, 0);
    const PluginStage<3> stage = vertex_stage(prepared, frames);
    Eigen::MatrixXd projected = folded;
    ASSERT_TRUE(polycube_plugin(prepared)->project(projected, stage));
    const PolycubeVerification v =
        verify_polycube(prepared.layout(), projected, prepared.input_volume);
    EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
    Index moved = 0;
    for (Index u = 0; u < prepared.mesh.num_vertices(); ++u) {
        // Up to the rounding of the planes' means, which project() takes first.
        const double shift = (projected.row(u) - folded.row(u)).norm();
        if (shift > 1e-9) ++moved;
        if (prepared.mesh.vertices(u, 0) >= 4.0) {
            EXPECT_LE(shift, 1e-12) << "vertex " << u;
        }
    }
    EXPECT_GT(moved, 0);
}

// The assembly takes f-SA (its translations hold the planes at their offsets), with or without
// a handle in the solid, and both maps are verified PolyCubes.
TEST(PolycubeSolve, SolidsWithAndWithoutAHandleAreAssembledWithTranslations) {
    for (const bool handle : {false, true}) {
        const PreparedPolycube prepared = prepared_shape(testing::bent(
            testing::voxel_tetrahedra(handle ? testing::ring() : testing::l_shape(), 2), 0.15));
        const PolycubeSolve solve = solve_polycube(prepared, {});
        ASSERT_TRUE(solve.success) << solve.message;
        EXPECT_LE(solve.verification.max_planarity, 1e-9);
        EXPECT_EQ(solve.options.variant, Variant::kFull);
    }
}

}  // namespace
}  // namespace sa
