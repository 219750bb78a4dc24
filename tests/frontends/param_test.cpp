#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <functional>

#include "frontends/param/parameterization.h"
#include "geometry/mesh/boundary_fans.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/quality/local_injectivity.h"
#include "optim/errors.h"

namespace sa {
namespace {

// A piece of helicoid around its axis: the vertex on the axis is a boundary vertex whose 12 rest
// triangles turn by 2.8 pi around it; with a small pitch their angles there sum to about 2.4 pi.
// A conformal map keeps those angles, so without the boundary barrier the layout overlaps itself
// there (a fold of the boundary, no inverted triangle).
SimplicialMesh helicoid(int steps, int rings) {
    const double turn = 2.8 * M_PI, pitch = 0.02;
    SimplicialMesh mesh;
    mesh.vertices.resize(1 + (steps + 1) * rings, 3);
    mesh.vertices.row(0) << 0.0, 0.0, 0.0;
    auto index = [&](int ring, int k) { return 1 + (ring - 1) * (steps + 1) + k; };
    for (int ring = 1; ring <= rings; ++ring) {
        for (int k = 0; k <= steps; ++k) {
            const double phi = turn * k / steps, r = double(ring) / rings;
            mesh.vertices.row(index(ring, k)) << r * std::cos(phi), r * std::sin(phi), pitch * phi;
        }
    }
    std::vector<Eigen::Vector3i> faces;
    for (int k = 0; k < steps; ++k) faces.emplace_back(0, index(1, k), index(1, k + 1));
    for (int ring = 1; ring < rings; ++ring) {
        for (int k = 0; k < steps; ++k) {
            faces.emplace_back(index(ring, k), index(ring + 1, k), index(ring + 1, k + 1));
            faces.emplace_back(index(ring, k), index(ring + 1, k + 1), index(ring, k + 1));
        }
    }
    mesh.simplices.resize(faces.size(), 3);
    for (std::size_t f = 0; f < faces.size(); ++f) mesh.simplices.row(f) = faces[f].transpose();
    return mesh;
}

ParameterizationOptions conformal_options() {
    ParameterizationOptions options;
    options.solver.mapping_distortion = DistortionType::kDifference;
    return options;
}

// The axis vertex of helicoid(12, 6) has a fan of 12 triangles, of helicoid(20, 6) 20: the
// barrier takes fans of any size.
TEST(Parameterization, BoundaryBarrierKeepsBoundaryAngleSumsBelow2Pi) {
    for (const int fan : {12, 20}) {
        const SimplicialMesh mesh = helicoid(fan, 6);
        ParameterizationOptions plain = conformal_options();
        const ParameterizationResult folded =
            parameterize(mesh, "helicoid", nullptr, InitialMap::kLscm, plain);
        EXPECT_EQ(folded.solve.verification.inverted, 0) << folded.message;
        EXPECT_GE(folded.boundary_violations_after, 1)
            << "the case should fold at its boundary without the barrier";

        ParameterizationOptions injective = conformal_options();
        injective.free_boundary_injective = true;
        const ParameterizationResult r =
            parameterize(mesh, "helicoid", nullptr, InitialMap::kLscm, injective);
        EXPECT_TRUE(r.success) << fan << ": " << r.message;
        EXPECT_EQ(r.solve.verification.inverted, 0);
        EXPECT_EQ(r.boundary_violations_after, 0) << r.message;
        const MeshTopology t = mesh_topology(mesh, "helicoid");
        const std::vector<BoundaryFan> fans = boundary_fans(mesh, t);
        const auto axis = std::find_if(fans.begin(), fans.end(),
                                       [](const BoundaryFan& f) { return f.vertex == 0; });
        ASSERT_NE(axis, fans.end());
        EXPECT_EQ(axis->triangles.size(), std::size_t(fan));
        for (double theta : boundary_angle_sums(fans, r.uv)) EXPECT_LT(theta, 2.0 * M_PI);
    }
}

TEST(Parameterization, VerticesOfNoTriangleAreLeftOutOfTheMap) {
    // A helicoid (a disk) with two vertices no triangle uses, one first and one last, and a
    // hole: every start is computed without them, and they do not enter the map.
    const SimplicialMesh disk = helicoid(24, 6);
    SimplicialMesh mesh;
    mesh.vertices.resize(disk.num_vertices() + 2, 3);
    mesh.vertices.row(0) << 5.0, 5.0, 5.0;
    mesh.vertices.middleRows(1, disk.num_vertices()) = disk.vertices;
    mesh.vertices.bottomRows(1) << -7.0, 0.0, 1.0;
    std::vector<Eigen::Vector3i> kept;
    for (Index f = 0; f < disk.num_simplices(); ++f) {
        if (f == 60 || f == 61) continue;  // two triangles of the second ring: a hole
        kept.push_back(disk.simplices.row(f).transpose().array() + 1);
    }
    mesh.simplices.resize(Index(kept.size()), 3);
    for (std::size_t f = 0; f < kept.size(); ++f)
        mesh.simplices.row(Index(f)) = kept[f].transpose();
    for (InitialMap start : {InitialMap::kLscm, InitialMap::kTutte}) {
        const ParameterizationResult r =
            parameterize(mesh, "loose", nullptr, start, conformal_options());
        EXPECT_TRUE(r.success) << r.message;
        EXPECT_EQ(r.unused_vertices, 2);
        EXPECT_EQ(r.uv.rows(), mesh.num_vertices());
        EXPECT_TRUE(r.uv.allFinite());
        EXPECT_NE(r.message.find("2 vertices belong to no triangle"), std::string::npos)
            << r.message;
    }
}

TEST(Parameterization, FullAndSubmeshModesBothVerifyABoundedMap) {
    // A bumpy disk whose LSCM map exceeds a tight conformal bound in places.
    SimplicialMesh mesh = grid_triangles(50, 50);
    Eigen::MatrixXd lifted(mesh.num_vertices(), 3);
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        const double x = mesh.vertices(v, 0), y = mesh.vertices(v, 1);
        lifted.row(v) << x, y,
            0.25 * std::exp(-30.0 * ((x - 0.4) * (x - 0.4) + (y - 0.6) * (y - 0.6)));
    }
    mesh.vertices = lifted;
    for (SolveMode mode : {SolveMode::kFull, SolveMode::kSubmesh}) {
        ParameterizationOptions options = conformal_options();
        options.solver.bound = 1.02;
        options.solver.mode = mode;
        const ParameterizationResult r =
            parameterize(mesh, "bump", nullptr, InitialMap::kLscm, options);
        EXPECT_GT(r.initial_quality.conformal.max, 1.05)
            << "LSCM should exceed the bound somewhere";
        EXPECT_TRUE(r.success) << to_string(mode) << ": " << r.message;
        EXPECT_TRUE(r.solve.verification.within_bound()) << r.solve.verification.describe();
        EXPECT_EQ(r.solve.mode, mode);
    }
}

TEST(Parameterization, OptimalBoundLowersTheLargestDistortion) {
    const SimplicialMesh mesh = helicoid(12, 4);
    ParameterizationOptions options = conformal_options();
    options.free_boundary_injective = true;
    options.optimal_bound_rounds = 4;
    const ParameterizationResult r =
        parameterize(mesh, "helicoid", nullptr, InitialMap::kLscm, options);
    ASSERT_TRUE(r.success) << r.message;
    ASSERT_GE(r.rounds.size(), 2u);
    EXPECT_LT(r.rounds[1].max_distortion, r.rounds[0].max_distortion);
    EXPECT_LE(r.reached_bound, r.rounds[0].max_distortion);
}

TEST(Parameterization, SubmeshOptimalBoundReachesTheFullModesBound) {
    // A disk with two bumps: LSCM's largest distortions sit on their slopes, far apart.
    SimplicialMesh mesh = grid_triangles(30, 30);
    Eigen::MatrixXd lifted(mesh.num_vertices(), 3);
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        const double x = mesh.vertices(v, 0), y = mesh.vertices(v, 1);
        auto bump = [&](double cx, double cy, double h) {
            return h * std::exp(-40.0 * ((x - cx) * (x - cx) + (y - cy) * (y - cy)));
        };
        lifted.row(v) << x, y, bump(0.3, 0.6, 0.2) + bump(0.7, 0.3, 0.15);
    }
    mesh.vertices = lifted;
    ParameterizationResult r[2];
    const SolveMode modes[2] = {SolveMode::kFull, SolveMode::kSubmesh};
    for (int k = 0; k < 2; ++k) {
        ParameterizationOptions options = conformal_options();
        options.optimal_bound_rounds = 20;
        options.solver.mode = modes[k];
        r[k] = parameterize(mesh, "two bumps", nullptr, InitialMap::kLscm, options);
        ASSERT_TRUE(r[k].success) << to_string(modes[k]) << ": " << r[k].message;
        EXPECT_EQ(r[k].solve.verification.inverted, 0);
        EXPECT_EQ(r[k].solve.mode, modes[k]);
        EXPECT_LE(r[k].reached_bound, r[k].solve.verification.bound);
    }
    EXPECT_GT(r[1].initial_quality.conformal.max, 1.1) << "LSCM should be distorted somewhere";
    // The submesh rounds solved around the simplices near the bound, not only those over it.
    EXPECT_GT(r[1].solve.submesh.start_near_bound, 0);
    EXPECT_GE(r[1].rounds.size(), 3u);
    // Each submesh round leaves most of the map as it was, yet the bound reached is the full
    // mode's (within a small tolerance: both stop at the same share of improvement per round).
    EXPECT_LT(r[1].reached_bound - 1.0, (r[0].reached_bound - 1.0) * 1.02)
        << "full " << r[0].reached_bound << ", submesh " << r[1].reached_bound;
    EXPECT_LT(r[1].reached_bound, r[1].rounds[1].max_distortion);
}

TEST(Parameterization, ABoundedSubmeshRunRemovesBranchPointsOfAFoldedStart) {
    // The unit square mapped by holomorphic polynomials with a critical point z0 45 or more rings
    // from the free boundary, beyond m_max: f - f(z0) ~ (z - z0)^tau there, a fold that turns
    // the loops around it tau times (a discrete branch point). No region whose outer vertices
    // keep their positions can repair it.
    const SimplicialMesh mesh = grid_triangles(100, 100);
    using C = std::complex<double>;
    const C centre(0.5, 0.5), z0(0.452, 0.503);
    const std::vector<std::function<C(C)>> maps = {
        [&](C z) { return (z - centre) - 0.5 / (z0 - centre) * (z - centre) * (z - centre); },
        [&](C z) { return 4.0 * (z - z0) * (z - z0) * (z - z0); }};
    for (std::size_t m = 0; m < maps.size(); ++m) {
        Eigen::MatrixXd start(mesh.num_vertices(), 2);
        for (Index v = 0; v < mesh.num_vertices(); ++v) {
            const C f = maps[m](C(mesh.vertices(v, 0), mesh.vertices(v, 1)));
            start.row(v) << f.real(), f.imag();
        }
        ParameterizationOptions options;
        options.solver.mapping_distortion = DistortionType::kLscm;
        options.solver.bound = 1.45;
        options.solver.mode = SolveMode::kSubmesh;
        const ParameterizationResult r =
            parameterize(mesh, "square", &start, InitialMap::kLscm, options);
        SCOPED_TRACE("map " + std::to_string(m) + ": " + r.message);
        const MeshTopology topology = mesh_topology(mesh, "square");
        EXPECT_TRUE(r.initial_quality.inverted > 0 ||
                    !branched_vertices(mesh, topology, start).empty())
            << "the start should fold";
        EXPECT_TRUE(r.success);
        EXPECT_TRUE(r.solve.verification.within_bound());
        EXPECT_EQ(r.solve.verification.branched, 0);
        EXPECT_GT(r.solve.submesh.start.branch_points_removed, 0)
            << r.solve.submesh.start.describe();
    }
}

// A flat closed surface with a one-vertex hole and sliver triangles (the class of OptCuts'
// golf.obj): a sphere squashed to 3% of its height, bent, the star of one vertex removed, and
// every fifth triangle made a sliver by moving a vertex close to its opposite edge. LSCM folds
// it, Simplex Assembly from LSCM or from Tutte does not assemble it, and Tutte's map has
// distortions in the hundreds (E_C = e^{d} overflows without the exponent's continuation).
SimplicialMesh flat_ball_with_slivers(int n) {
    const SimplicialMesh sphere = sphere_triangles(n);
    Index hole = 0;
    const Eigen::Vector3d toward = Eigen::Vector3d(-0.3, 0.9, 0.2).normalized();  // on the rim
    for (Index v = 0; v < sphere.num_vertices(); ++v) {
        if (sphere.vertices.row(v).dot(toward) > sphere.vertices.row(hole).dot(toward)) hole = v;
    }
    std::vector<Eigen::Vector3i> kept;
    for (Index s = 0; s < sphere.num_simplices(); ++s) {
        const Eigen::Vector3i f = sphere.simplices.row(s).transpose();
        if (f[0] != hole && f[1] != hole && f[2] != hole) kept.push_back(f);
    }
    SimplicialMesh mesh;
    mesh.vertices = sphere.vertices;
    mesh.simplices.resize(kept.size(), 3);
    for (std::size_t k = 0; k < kept.size(); ++k) mesh.simplices.row(k) = kept[k].transpose();
    // The hole's vertex is unused: drop it (the last index takes its place).
    const Index last = mesh.num_vertices() - 1;
    mesh.vertices.row(hole) = mesh.vertices.row(last);
    mesh.vertices.conservativeResize(last, 3);
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        for (int k = 0; k < 3; ++k) {
            if (mesh.simplices(s, k) == last) mesh.simplices(s, k) = int(hole);
        }
    }
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        const double x = mesh.vertices(v, 0);
        mesh.vertices(v, 1) = 1.3 * mesh.vertices(v, 1) + 0.5 * std::sin(2.0 * x);
        mesh.vertices(v, 2) *= 0.03;
    }
    std::vector<unsigned char> moved(mesh.num_vertices(), 0);
    for (Index s = 0; s < mesh.num_simplices(); s += 5) {
        const Index a = mesh.simplices(s, 0), b = mesh.simplices(s, 1), c = mesh.simplices(s, 2);
        if (moved[a] || moved[b] || moved[c]) continue;
        moved[a] = 1;
        const Eigen::RowVector3d middle = 0.5 * (mesh.vertices.row(b) + mesh.vertices.row(c));
        mesh.vertices.row(a) = 0.05 * mesh.vertices.row(a) + 0.95 * middle;
    }
    return mesh;
}

// Every triangle of `uv` positively oriented and of non-negligible area, measured here.
void expect_valid_layout(const SimplicialMesh& mesh, const Eigen::MatrixXd& uv) {
    double largest = 0.0;
    std::vector<double> area(mesh.num_simplices());
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        const Eigen::RowVector2d a = uv.row(mesh.simplices(s, 1)) - uv.row(mesh.simplices(s, 0)),
                                 b = uv.row(mesh.simplices(s, 2)) - uv.row(mesh.simplices(s, 0));
        area[s] = a.x() * b.y() - a.y() * b.x();
        largest = std::max(largest, std::abs(area[s]));
    }
    for (Index s = 0; s < mesh.num_simplices(); ++s)
        EXPECT_GT(area[s], 1e-14 * largest) << "triangle " << s;
}

TEST(Parameterization, FallsBackToTutteWhenTheLscmStartFoldsBeyondRepair) {
    const SimplicialMesh mesh = flat_ball_with_slivers(8);
    ParameterizationOptions without = conformal_options();
    without.fallback = false;
    const ParameterizationResult failed =
        parameterize(mesh, "flat ball", nullptr, InitialMap::kLscm, without);
    ASSERT_FALSE(failed.success) << "the case should defeat Simplex Assembly from LSCM";
    EXPECT_GT(failed.initial_quality.inverted, 0) << "LSCM should fold";

    const ParameterizationResult r =
        parameterize(mesh, "flat ball", nullptr, InitialMap::kLscm, conformal_options());
    EXPECT_TRUE(r.success) << r.message;
    ASSERT_TRUE(r.fallback.used);
    ASSERT_TRUE(r.fallback.start.has_value()) << r.message;
    EXPECT_EQ(*r.fallback.start, TutteWeights::kMeanValue) << r.message;
    EXPECT_EQ(r.fallback.reason, FallbackReason::kNotVerified);
    ASSERT_FALSE(r.fallback.starts.empty());
    EXPECT_EQ(r.fallback.starts.front().outcome, TriedStartOutcome::kVerified);
    EXPECT_GT(r.fallback.rounds.size(), 1u) << "the exponent's continuation should take rounds";
    EXPECT_EQ(r.solve.verification.inverted, 0);
    EXPECT_EQ(r.solve.verification.degenerate, 0);
    expect_valid_layout(mesh, r.uv);

    // The optimal bound goes on from the fallback's map.
    ParameterizationOptions optimal = conformal_options();
    optimal.optimal_bound_rounds = 10;
    const ParameterizationResult o =
        parameterize(mesh, "flat ball", nullptr, InitialMap::kLscm, optimal);
    EXPECT_TRUE(o.success) << o.message;
    EXPECT_TRUE(o.fallback.used);
    EXPECT_LT(o.reached_bound, r.reached_bound);
    expect_valid_layout(mesh, o.uv);
}

// A finer ball: the Tutte start's slivers have s d ~ 600, beyond the barrier's exponent cap,
// and no fixed vertex forces them (only one anchored triangle is fixed): the exponent
// continuation lowers them (a stage that skipped such a start kept the Tutte map, distortion
// ~1200).
TEST(Parameterization, TheFallbackLowersSliversBeyondTheExponentCap) {
    const SimplicialMesh mesh = flat_ball_with_slivers(12);
    const ParameterizationResult r =
        parameterize(mesh, "flat ball", nullptr, InitialMap::kLscm, conformal_options());
    EXPECT_TRUE(r.success) << r.message;
    ASSERT_TRUE(r.fallback.start.has_value()) << r.message;
    ASSERT_GT(r.fallback.rounds.size(), 1u);
    EXPECT_GT(r.fallback.rounds.front().max_distortion_before, 500.0);
    EXPECT_LT(r.fallback.rounds.front().s, 0.1);
    EXPECT_LT(r.solve.verification.max_distortion, 20.0) << r.message;
    expect_valid_layout(mesh, r.uv);
}

TEST(Parameterization, AnUnreachableBoundIsReportedWithAMapWithoutFoldovers) {
    const SimplicialMesh mesh = flat_ball_with_slivers(8);
    ParameterizationOptions options = conformal_options();
    options.solver.bound = 1.001;  // a sliver cannot stay a similarity of itself in a flat map
    const ParameterizationResult r =
        parameterize(mesh, "flat ball", nullptr, InitialMap::kLscm, options);
    EXPECT_FALSE(r.success);
    ASSERT_TRUE(r.fallback.used);
    EXPECT_TRUE(r.solve.verification.passed()) << r.message;
    EXPECT_FALSE(r.solve.verification.within_bound());
    EXPECT_NE(r.message.find("was not reached"), std::string::npos) << r.message;
    expect_valid_layout(mesh, r.uv);
}

// The unit sphere without the star of its vertex nearest to +z, stretched `stretch` times along x:
// a long, nearly closed surface. Its conformal maps shrink parts of it by many orders of magnitude
// (the optimum is not representable in doubles); Tutte's map of it has no degenerate triangle.
// At stretch 1000 LSCM folds it, and without the undo no Tutte start's descent verifies.
SimplicialMesh stretched_sphere_with_hole(int n, double stretch) {
    const SimplicialMesh sphere = sphere_triangles(n);
    Index hole = 0;
    for (Index v = 0; v < sphere.num_vertices(); ++v) {
        if (sphere.vertices(v, 2) > sphere.vertices(hole, 2)) hole = v;
    }
    SimplicialMesh mesh;
    mesh.vertices.resize(sphere.num_vertices() - 1, 3);
    for (Index v = 0, w = 0; v < sphere.num_vertices(); ++v) {
        if (v == hole) continue;
        mesh.vertices.row(w++) = sphere.vertices.row(v);
    }
    mesh.vertices.col(0) *= stretch;
    std::vector<Eigen::Vector3i> kept;
    for (Index s = 0; s < sphere.num_simplices(); ++s) {
        Eigen::Vector3i f = sphere.simplices.row(s).transpose();
        if (f[0] == hole || f[1] == hole || f[2] == hole) continue;
        for (int k = 0; k < 3; ++k) f[k] -= f[k] > hole ? 1 : 0;
        kept.push_back(f);
    }
    mesh.simplices.resize(kept.size(), 3);
    for (std::size_t k = 0; k < kept.size(); ++k) mesh.simplices.row(k) = kept[k].transpose();
    return mesh;
}

// A round of the vertex descent that turns its valid start into a map with numerically degenerate
// triangles is undone: whatever the requested start does, a disk gets a verified map.
TEST(Parameterization, TheFallbackKeepsAValidMapWhenTheEnergyShrinksTrianglesAway) {
    const SimplicialMesh mesh = stretched_sphere_with_hole(8, 1000.0);
    const ParameterizationResult r =
        parameterize(mesh, "stretched sphere", nullptr, InitialMap::kLscm, conformal_options());
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_EQ(r.solve.verification.inverted, 0) << r.message;
    EXPECT_EQ(r.solve.verification.degenerate, 0) << r.message;
    expect_valid_layout(mesh, r.uv);
}

TEST(Parameterization, RejectsMeshesThatAreNotDisks) {
    SimplicialMesh closed;
    closed.vertices.resize(4, 3);
    closed.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
    closed.simplices.resize(4, 3);
    closed.simplices << 0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2;
    EXPECT_THROW(parameterize(closed, "closed", nullptr, InitialMap::kLscm, conformal_options()),
                 InputError);
    SimplicialMesh fan;  // three triangles on one edge
    fan.vertices.resize(5, 3);
    fan.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1;
    fan.simplices.resize(3, 3);
    fan.simplices << 0, 1, 2, 1, 0, 3, 0, 1, 4;
    EXPECT_THROW(parameterize(fan, "fan", nullptr, InitialMap::kLscm, conformal_options()),
                 InputError);
}

}  // namespace
}  // namespace sa
