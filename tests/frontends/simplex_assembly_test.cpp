#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "frontends/simplex_assembly/map_solve.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/quality/handle_feasibility.h"
#include "tests/frontends/scrambled_problem.h"

namespace sa {
namespace {

void expect_verified(const SimplexAssemblyResult& r, const MappingProblem& p) {
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_EQ(r.verification.inverted, 0);
    EXPECT_EQ(r.verification.degenerate, 0);
    EXPECT_LE(r.verification.handle_error, r.verification.handle_tolerance);
    EXPECT_GT(r.initial_quality.inverted, 0) << "the test should start from a folded map";
    // Independently of the driver's own verification: orientation of every output simplex.
    const int d = p.mesh.simplex_dimension();
    for (Index s = 0; s < p.mesh.num_simplices(); ++s) {
        Eigen::MatrixXd rest(d, d), out(d, d);
        for (int k = 0; k < d; ++k) {
            rest.col(k) = (p.mesh.vertices.row(p.mesh.simplices(s, k + 1)) -
                           p.mesh.vertices.row(p.mesh.simplices(s, 0)))
                              .transpose();
            out.col(k) = (r.positions.row(p.mesh.simplices(s, k + 1)) -
                          r.positions.row(p.mesh.simplices(s, 0)))
                             .transpose();
        }
        EXPECT_GT(rest.determinant() * out.determinant(), 0.0) << "simplex " << s;
    }
}

TEST(SimplexAssembly, UntanglesAFolded2DMap) {
    const MappingProblem p = scrambled(grid_triangles(12, 12), 0.12, 1);
    SimplexAssemblyOptions options;
    const SimplexAssemblyResult r = run_simplex_assembly(p, options);
    expect_verified(r, p);
    EXPECT_TRUE(r.assembled);
    EXPECT_LT(r.num_translation_simplices, p.mesh.num_simplices() / 4);  // r-SA: few translations
}

TEST(SimplexAssembly, UntanglesAFolded3DMap) {
    const MappingProblem p = scrambled(grid_tetrahedra(4, 4, 4), 0.12, 2);
    SimplexAssemblyOptions options;
    const SimplexAssemblyResult r = run_simplex_assembly(p, options);
    expect_verified(r, p);
}

TEST(SimplexAssembly, ABoundaryThatTurnsTwiceIsNotCalledASuccess) {
    // A disk whose boundary handles go twice around its centre: no inverted triangle is needed,
    // but every map with this boundary wraps around an interior vertex twice (a branch point).
    const int n = 16;
    MappingProblem p;
    p.mesh.vertices.resize(n + 1, 2);
    p.mesh.simplices.resize(n, 3);
    p.initial.resize(n + 1, 2);
    p.mesh.vertices.row(n) << 0.0, 0.0;
    p.initial.row(n) << 0.05, 0.0;
    for (int k = 0; k < n; ++k) {
        const double a = 2.0 * M_PI * k / n;
        p.mesh.vertices.row(k) << std::cos(a), std::sin(a);
        p.initial.row(k) << std::cos(2.0 * a), std::sin(2.0 * a);
        p.mesh.simplices.row(k) << n, k, (k + 1) % n;
        p.handles.push_back(k);
    }
    const SimplexAssemblyResult r = run_simplex_assembly(p, SimplexAssemblyOptions{});
    EXPECT_FALSE(r.success) << r.message;
    EXPECT_EQ(r.verification.inverted, 0) << r.message;
    EXPECT_EQ(r.verification.branched, 1) << r.message;
    EXPECT_NE(r.message.find("not locally injective"), std::string::npos) << r.message;
}

// Each check of handle_feasibility.h stops the run before the first iteration: the logger sees
// no progress row, and the exception carries the diagnosis.
TEST(SimplexAssembly, HandlesThatRuleOutASolutionStopBeforeOptimizing) {
    MappingProblem box = scrambled(grid_tetrahedra(3, 3, 3), 0.05, 2);
    std::vector<MappingProblem> cases;
    {
        MappingProblem mirrored = box;  // every fixed simplex inverted
        for (Index h : mirrored.handles) mirrored.initial(h, 0) *= -1.0;
        cases.push_back(mirrored);
    }
    {
        MappingProblem twice = box;  // one handle at two places
        twice.targets.resize(box.handles.size() + 1, 3);
        for (std::size_t k = 0; k < box.handles.size(); ++k)
            twice.targets.row(k) = box.initial.row(box.handles[k]);
        twice.handles.push_back(box.handles[3]);
        twice.targets.row(box.handles.size()) = box.initial.row(box.handles[3]);
        twice.targets(box.handles.size(), 2) += 0.3;
        cases.push_back(twice);
    }
    {
        MappingProblem collapsed = scrambled(grid_triangles(6, 6), 0.03, 3);  // edge 0-1
        collapsed.initial.row(1) = collapsed.initial.row(0);
        cases.push_back(collapsed);
    }
    const std::vector<std::string> expected = {"are inverted", "fixed twice", "both ends"};
    for (std::size_t c = 0; c < cases.size(); ++c) {
        int rows = 0;
        SimplexAssemblyObserver observer;
        observer.logger = [&rows](const std::string&) { ++rows; };
        try {
            run_simplex_assembly(cases[c], SimplexAssemblyOptions{}, observer);
            ADD_FAILURE() << "case " << c << ": no InfeasibleProblemError";
        } catch (const InfeasibleProblemError& e) {
            EXPECT_NE(std::string(e.what()).find(expected[c]), std::string::npos) << e.what();
            EXPECT_FALSE(e.diagnosis().feasible());
        }
        EXPECT_EQ(rows, 0) << "case " << c << ": something was optimized";
    }
    // The same problems with feasible handles run as usual.
    EXPECT_TRUE(run_simplex_assembly(box, SimplexAssemblyOptions{}).success);
}

}  // namespace
}  // namespace sa
