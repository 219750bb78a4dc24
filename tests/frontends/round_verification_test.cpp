#include "frontends/simplex_assembly/detail/round_verification.h"

#include <gtest/gtest.h>

#include <complex>

#include "geometry/mesh/mesh_generators.h"

namespace sa {
namespace {

// verify_changes() against verify_result() on the same positions: a map verified whole, then
// moved at a few vertices (a valid stretch, a fold, a vertex wrapped twice around).
TEST(RoundVerification, MeasuresWhatTheWholeVerificationMeasures) {
    MappingProblem p;
    p.mesh = grid_triangles(10, 10);
    p.initial = p.mesh.vertices.leftCols(2);
    p.source = "grid";
    SimplexAssemblyOptions options;
    options.bound = 1.5;
    StageTimes times;
    auto prepared = prepare_problem<2>(p, options, times);
    VerifiedMap state;
    auto compare = [&](const Eigen::MatrixXd& positions, const char* what) {
        SimplexAssemblyResult part, whole;
        part.positions = whole.positions = positions;
        verify_changes<2>(*prepared, options, part, state);
        verify_result<2>(p, options, whole, &prepared->topology);
        const Verification &a = part.verification, &b = whole.verification;
        EXPECT_EQ(a.inverted, b.inverted) << what;
        EXPECT_EQ(a.degenerate, b.degenerate) << what;
        EXPECT_EQ(a.branched, b.branched) << what;
        EXPECT_EQ(a.max_distortion, b.max_distortion) << what;
        EXPECT_EQ(a.within_bound(), b.within_bound()) << what;
        EXPECT_EQ(part.success, whole.success) << what;
        return a;
    };
    Eigen::MatrixXd x = p.initial;
    EXPECT_EQ(compare(x, "the rest shape").max_distortion, 1.0);
    // Vertex (5, 5) of the 11 x 11 grid moved a third of a cell: distorted, still valid.
    const Index centre = 5 * 11 + 5;
    x.row(centre) += Eigen::RowVector2d(0.033, 0.0);
    const Verification stretched = compare(x, "a stretch");
    EXPECT_GT(stretched.max_distortion, 1.0);
    EXPECT_EQ(stretched.inverted, 0);
    // Moved past its neighbour: triangles fold.
    x.row(centre) += Eigen::RowVector2d(0.2, 0.0);
    EXPECT_GT(compare(x, "a fold").inverted, 0);
    // Back where it was: the measurements of the untouched simplices were kept.
    x.row(centre) = p.initial.row(centre);
    EXPECT_EQ(compare(x, "restored").max_distortion, 1.0);
}

TEST(RoundVerification, FindsABranchPointWhereTheMapMoved) {
    // A wheel of 8 triangles around vertex 0, then mapped by z -> z^2: every triangle positive,
    // the centre's angles sum to 4 pi.
    MappingProblem p;
    p.mesh.vertices.resize(9, 2);
    p.mesh.simplices.resize(8, 3);
    p.mesh.vertices.row(0) << 0.0, 0.0;
    for (int k = 0; k < 8; ++k) {
        p.mesh.vertices.row(k + 1) << std::cos(M_PI * k / 4), std::sin(M_PI * k / 4);
        p.mesh.simplices.row(k) << 0, k + 1, (k + 1) % 8 + 1;
    }
    p.initial = p.mesh.vertices;
    p.source = "wheel";
    SimplexAssemblyOptions options;
    StageTimes times;
    auto prepared = prepare_problem<2>(p, options, times);
    VerifiedMap state;
    SimplexAssemblyResult first;
    first.positions = p.initial;
    verify_changes<2>(*prepared, options, first, state);
    EXPECT_TRUE(first.success) << first.verification.describe();
    SimplexAssemblyResult wrapped;
    wrapped.positions = p.initial;
    for (Index v = 1; v < 9; ++v) {
        const std::complex<double> z(p.initial(v, 0), p.initial(v, 1)), w = z * z;
        wrapped.positions.row(v) << w.real(), w.imag();
    }
    verify_changes<2>(*prepared, options, wrapped, state);
    EXPECT_EQ(wrapped.verification.inverted, 0);
    EXPECT_EQ(wrapped.verification.degenerate, 0);
    EXPECT_EQ(wrapped.verification.branched, 1);
    EXPECT_FALSE(wrapped.success);
}

}  // namespace
}  // namespace sa
