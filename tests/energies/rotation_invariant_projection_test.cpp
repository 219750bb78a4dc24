#include "energies/rotation_invariant_projection.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "energies/simplex_energy.h"
#include "energies/vertex_copy_energies.h"

namespace sa {
namespace {

template <int D>
Mat<D> random_rotation(std::mt19937& rng) {
    std::normal_distribution<double> n;
    Mat<D> M;
    for (int i = 0; i < D * D; ++i) M(i) = n(rng);
    Mat<D> Q = M.householderQr().householderQ();
    if (Q.determinant() < 0) Q.col(0) *= -1.0;
    return Q;
}

// R1 diag(s) R2 with the given singular values: generic ones, or equal ones where the singular
// vectors are not unique.
template <int D>
Mat<D> matrix_with_singular_values(const Vec<D>& s, std::mt19937& rng) {
    return random_rotation<D>(rng) * s.asDiagonal() * random_rotation<D>(rng);
}

/// Ascending, by a dynamic-size solver (a fixed-size one per block size is slow to compile).
Eigen::VectorXd eigenvalues_of(const Eigen::MatrixXd& h) {
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(h, Eigen::EigenvaluesOnly).eigenvalues();
}

template <int D>
Vec<D * D> vec(const Mat<D>& A) {
    return Eigen::Map<const Vec<D * D>>(A.data());
}

// Checks the projection through singular vectors against the eigen-decomposition of the whole
// block, for every barrier and mapping distortion, every mode and several kinds of A.
template <int D>
void check_against_eigen_decomposition() {
    constexpr int N = D * D;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.3, 3.0);
    std::vector<Vec<D>> singular_values;
    for (int k = 0; k < 6; ++k) {
        Vec<D> s;
        for (int i = 0; i < D; ++i) s[i] = u(rng);
        singular_values.push_back(s);
    }
    singular_values.push_back(Vec<D>::Constant(1.7));                           // a similarity
    singular_values.push_back(Vec<D>::Constant(0.8) + 1e-9 * Vec<D>::Unit(0));  // nearly one
    std::optional<DistortionType> none;
    int blocks_changed = 0;
    for (DistortionType barrier :
         {DistortionType::kConformal, DistortionType::kVolumetric, DistortionType::kIsometric}) {
        std::vector<std::optional<DistortionType>> mappings{none};
        for (DistortionType t : all_distortions()) mappings.push_back(t);
        for (const auto& mapping : mappings) {
            for (ProjectionMode mode :
                 {ProjectionMode::kClamp, ProjectionMode::kAbs, ProjectionMode::kShift}) {
                for (const Vec<D>& s : singular_values) {
                    const Mat<D> A = matrix_with_singular_values<D>(s, rng);
                    SimplexEnergyOptions options;
                    options.barrier_distortion = barrier;
                    options.barrier.bound = 200.0;
                    options.mapping_distortion = mapping;
                    options.mu = 3.0;
                    const SimplexEnergy<D> energy(options, {0.7},
                                                  {matrix_with_singular_values<D>(s, rng)});
                    Vec<N> g;
                    Mat<N> h;
                    const double value = energy.value_gradient_hessian(0, vec<D>(A), g, h);
                    ASSERT_TRUE(std::isfinite(value));
                    Mat<N> expected = h, projected = h;
                    const bool expected_changed = project_hessian_block<N>(expected, mode, 1e-8);
                    const bool changed =
                        energy.project_hessian(0, vec<D>(A), projected, mode, 1e-8);
                    const std::string what = to_string(barrier) + " barrier, mapping " +
                                             (mapping ? to_string(*mapping) : "none") + ", " +
                                             to_string(mode) + ", singular values " +
                                             ::testing::PrintToString(s.transpose());
                    EXPECT_EQ(changed, expected_changed) << what;
                    EXPECT_LE((projected - expected).norm(), 1e-9 * h.norm()) << what;
                    blocks_changed += changed;
                }
            }
        }
    }
    EXPECT_GT(blocks_changed, 0);  // the comparison covered indefinite blocks
}

TEST(RotationInvariantProjection, MatchesEigenDecompositionIn2D) {
    check_against_eigen_decomposition<2>();
}

TEST(RotationInvariantProjection, MatchesEigenDecompositionIn3D) {
    check_against_eigen_decomposition<3>();
}

TEST(RotationInvariantProjection, ResultIsPositiveDefinite) {
    std::mt19937 rng(11);
    const Mat<3> A = matrix_with_singular_values<3>(Vec<3>(2.5, 0.4, 0.9), rng);
    SimplexEnergyOptions options;
    const SimplexEnergy<3> energy(options, {1.0});
    Vec<9> g;
    Mat<9> h;
    energy.value_gradient_hessian(0, vec<3>(A), g, h);
    ASSERT_LT(eigenvalues_of(h)(0), 0.0);
    const double scale = h.norm();
    ASSERT_TRUE(energy.project_hessian(0, vec<3>(A), h, ProjectionMode::kClamp, 1e-6));
    EXPECT_GE(eigenvalues_of(h)(0), 1e-6 - 1e-12 * scale);
}

// The vertex-copy energy projects in A: L^T P(H_A) L, positive semidefinite, with L's null space
// (the tetrahedron's translations) left at eigenvalue 0.
TEST(RotationInvariantProjection, VertexEnergyProjectsInA) {
    std::mt19937 rng(5);
    const Mat<3> rest_inverse = matrix_with_singular_values<3>(Vec<3>(1.2, 0.7, 0.9), rng);
    const VertexSimplexEnergy<3> energy(SimplexEnergy<3>(SimplexEnergyOptions{}, {1.0}),
                                        {rest_inverse});
    // Copies x_0 = 0, x_1..x_3 the columns of A R with a stretched A, whose barrier Hessian is
    // indefinite.
    const Mat<3> A = matrix_with_singular_values<3>(Vec<3>(2.5, 0.4, 0.9), rng);
    const Mat<3> edges = A * rest_inverse.inverse();
    Vec<12> x = Vec<12>::Zero();
    for (int c = 0; c < 3; ++c) x.segment<3>(3 * (c + 1)) = edges.col(c);
    Vec<12> g;
    Mat<12> h;
    energy.value_gradient_hessian(0, x, g, h);
    const double scale = h.norm();
    ASSERT_LT(eigenvalues_of(h)(0), -1e-6 * scale);
    ASSERT_TRUE(energy.project_hessian(0, x, h, ProjectionMode::kClamp, 1e-8));
    const Eigen::VectorXd eigenvalues = eigenvalues_of(h);
    EXPECT_GE(eigenvalues(0), -1e-12 * scale);
    EXPECT_LE(eigenvalues(2), 1e-12 * scale);  // three translations
    EXPECT_GT(eigenvalues(3), 1e-9);

    // Translating every copy changes nothing.
    Vec<12> shift;
    for (int k = 0; k < 4; ++k) shift.segment<3>(3 * k) = Vec<3>(0.3, -1.0, 2.0);
    EXPECT_LE((h * shift).norm(), 1e-12 * scale);
}

TEST(RotationInvariantProjection, InvertedMatrixFallsBackToEigenDecomposition) {
    Mat<2> A;
    A << 1.0, 0.2, 0.1, -0.5;  // det < 0
    Mat<4> h;
    h << 2, 1, 0, 0, 1, -3, 0, 0, 0, 0, 1, 0.5, 0, 0, 0.5, -1;
    Mat<4> expected = h;
    project_hessian_block<4>(expected, ProjectionMode::kClamp, 1e-8);
    EXPECT_TRUE(project_rotation_invariant_hessian<2>(A, h, ProjectionMode::kClamp, 1e-8));
    EXPECT_LE((h - expected).norm(), 1e-12);
}

}  // namespace
}  // namespace sa
