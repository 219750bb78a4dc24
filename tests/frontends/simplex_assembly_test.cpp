#include <gtest/gtest.h>

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

}  // namespace
}  // namespace sa
