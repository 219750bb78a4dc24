#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "frontends/simplex_assembly/simplex_assembly.h"
#include "geometry/mesh_generators.h"
#include "geometry/mesh_topology.h"

namespace sa {
namespace {

// The boundary stays (the handles), interior vertices are scattered: many inverted simplices.
MappingProblem scrambled(const SimplicialMesh& mesh, double amount, unsigned seed) {
    MappingProblem p;
    p.mesh = mesh;
    p.initial = mesh.vertices;
    const MeshTopology t = mesh_topology(mesh, "generated");
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-amount, amount);
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        if (t.boundary_vertex[v]) {
            p.handles.push_back(v);
        } else {
            for (int c = 0; c < mesh.vertices.cols(); ++c) p.initial(v, c) += u(rng);
        }
    }
    return p;
}

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

}  // namespace
}  // namespace sa
