#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <random>

#include "energies/simplex_energy.h"
#include "optim/derivative_check.h"
#include "optim/errors.h"

namespace sa {
namespace {

template <int D>
Mat<D> random_positive_matrix(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    while (true) {
        Mat<D> A = Mat<D>::Identity();
        for (int i = 0; i < D * D; ++i) A(i) += 0.6 * u(rng);
        if (A.determinant() > 0.2) return A;
    }
}

template <int D>
Vec<D * D> vec(const Mat<D>& A) {
    return Eigen::Map<const Vec<D * D>>(A.data());
}

// The distortion from singular values, straight from the definitions of section 3.
template <int D>
double reference_distortion(DistortionType type, const Mat<D>& A) {
    const Vec<D> s = Eigen::JacobiSVD<Mat<D>>(A).singularValues();
    double sum_sq = 0, inv_sq = 0, arap = 0, gl = 0, asap = 0, det = s.prod();
    for (int k = 0; k < D; ++k) {
        sum_sq += s[k] * s[k];
        inv_sq += 1.0 / (s[k] * s[k]);
        arap += (s[k] - 1) * (s[k] - 1);
        gl += (s[k] * s[k] - 1) * (s[k] * s[k] - 1);
        for (int l = 0; l < D; ++l) asap += (s[k] - s[l]) * (s[k] - s[l]);
    }
    double conformal = 1.0;
    for (int k = 0; k < D; ++k)
        for (int l = k + 1; l < D; ++l) conformal *= 0.5 * (s[k] / s[l] + s[l] / s[k]);
    const double volumetric = 0.5 * (det + 1.0 / det);
    if constexpr (D == 3) {
        // The closed form (|A|^2 |A^-1|^2 - 1) / 8 differs from the product form in 3D; both are
        // 1 at a similarity. The energy uses the closed form of the paper.
        conformal = (sum_sq * inv_sq - 1.0) / 8.0;
    }
    switch (type) {
        case DistortionType::kConformal:
            return conformal;
        case DistortionType::kVolumetric:
            return volumetric;
        case DistortionType::kIsometric:
            return 0.5 * conformal + 0.5 * volumetric;
        case DistortionType::kDirichlet:
            return sum_sq;
        case DistortionType::kSymmetricDirichlet:
            return sum_sq + inv_sq;
        case DistortionType::kGreenLagrange:
            return gl;
        case DistortionType::kAsap:
            return asap;
        case DistortionType::kArap:
            return arap;
        case DistortionType::kLscm:
            return 0.5 * asap;
        case DistortionType::kDifference:
            break;
    }
    return 0.0;
}

template <int D>
void check_all_distortions() {
    std::mt19937 rng(D);
    for (int trial = 0; trial < 20; ++trial) {
        const Mat<D> A = random_positive_matrix<D>(rng);
        const MatrixInvariants<double> m = matrix_invariants<D>(A, true);
        for (DistortionType type : all_distortions()) {
            if (type == DistortionType::kDifference) continue;
            EXPECT_NEAR(distortion<D>(type, m), reference_distortion<D>(type, A), 1e-10)
                << to_string(type) << " D=" << D;
        }
    }
}

TEST(Distortion, ValuesMatchSingularValueDefinitions2D) {
    check_all_distortions<2>();
}
TEST(Distortion, ValuesMatchSingularValueDefinitions3D) {
    check_all_distortions<3>();
}

template <int D>
void check_equal_one_at_similarity() {
    std::mt19937 rng(7);
    const Mat<D> rotation = Eigen::JacobiSVD<Mat<D>>(random_positive_matrix<D>(rng),
                                                     Eigen::ComputeFullU | Eigen::ComputeFullV)
                                .matrixU();
    Mat<D> R = rotation;
    if (R.determinant() < 0.0) R.col(0) *= -1.0;
    const MatrixInvariants<double> m = matrix_invariants<D>(2.5 * R, false);
    EXPECT_NEAR(distortion<D>(DistortionType::kConformal, m), 1.0, 1e-12);
    const MatrixInvariants<double> r = matrix_invariants<D>(R, true);
    EXPECT_NEAR(distortion<D>(DistortionType::kIsometric, r), 1.0, 1e-12);
    EXPECT_NEAR(distortion<D>(DistortionType::kArap, r), 0.0, 1e-12);
}

TEST(Distortion, ConformalIsOneAtASimilarityAndIsometricAtARotation) {
    check_equal_one_at_similarity<2>();
    check_equal_one_at_similarity<3>();
}

template <int D>
void check_energy_derivatives(const SimplexEnergyOptions& options, const std::string& label) {
    std::mt19937 rng(11 * D);
    std::vector<double> weights(5, 0.3);
    std::vector<Mat<D>> references;
    for (int i = 0; i < 5; ++i) references.push_back(random_positive_matrix<D>(rng));
    const SimplexEnergy<D> energy(options, weights, references);
    for (Index i = 0; i < 5; ++i) {
        Mat<D> A = random_positive_matrix<D>(rng);
        if (energy.barrier_distortion(A) >= options.barrier.bound) A = Mat<D>::Identity() * 1.1;
        const DerivativeCheck check = check_derivatives(energy, i, vec<D>(A), 1e-6);
        EXPECT_TRUE(check.passes(2e-6))
            << label << " D=" << D << ": value " << check.value << ", gradient error "
            << check.gradient_error << ", Hessian error " << check.hessian_error;
    }
}

TEST(SimplexEnergy, DerivativesOfEveryMappingDistortionMatchFiniteDifferences) {
    for (DistortionType type : all_distortions()) {
        SimplexEnergyOptions options;
        options.mapping_distortion = type;
        options.mu = 2.0;
        check_energy_derivatives<2>(options, to_string(type));
        check_energy_derivatives<3>(options, to_string(type));
    }
}

// In 3D the energy is differentiated in the four invariants and chained to vec(A); the same
// energy differentiated operation by operation in vec(A) (Dual<9>) must agree to rounding.
TEST(SimplexEnergy, ChainedThroughTheInvariantsEqualsDifferentiatingInVecA) {
    std::mt19937 rng(23);
    for (DistortionType type : all_distortions()) {
        if (type == DistortionType::kDifference) continue;
        SimplexEnergyOptions options;
        options.barrier_distortion = DistortionType::kVolumetric;
        options.barrier.bound = 6.0;
        options.mapping_distortion = type;
        options.mu = 2.0;
        const SimplexEnergy<3> energy(options, {0.3});
        for (int trial = 0; trial < 5; ++trial) {
            Mat<3> A = random_positive_matrix<3>(rng);
            if (energy.barrier_distortion(A) >= options.barrier.bound) A = 1.1 * Mat<3>::Identity();
            const auto m = matrix_invariants_with_derivatives<3>(A, needs_sigma_sum(type));
            Dual<9> expected =
                barrier(distortion<3>(options.barrier_distortion, m), options.barrier);
            expected += (options.mu * 0.3) * distortion<3>(type, m);
            Vec<9> gradient;
            Mat<9> hessian;
            const double value = energy.value_gradient_hessian(0, vec<3>(A), gradient, hessian);
            const double scale = expected.hessian.cwiseAbs().maxCoeff();
            EXPECT_NEAR(value, expected.value, 1e-12 * std::abs(expected.value)) << to_string(type);
            EXPECT_LT((gradient - expected.gradient).cwiseAbs().maxCoeff(),
                      1e-12 * expected.gradient.cwiseAbs().maxCoeff())
                << to_string(type);
            EXPECT_LT((hessian - expected.hessian).cwiseAbs().maxCoeff(), 1e-12 * scale)
                << to_string(type);
        }
    }
}

TEST(SimplexEnergy, DerivativesOfEveryBarrierMatchFiniteDifferences) {
    for (DistortionType type :
         {DistortionType::kConformal, DistortionType::kVolumetric, DistortionType::kIsometric}) {
        for (double bound : {kInfinity, 6.0}) {
            SimplexEnergyOptions options;
            options.barrier_distortion = type;
            options.barrier.bound = bound;
            options.barrier.s = 0.7;
            const std::string label = to_string(type) + " K=" + std::to_string(bound);
            check_energy_derivatives<2>(options, label);
            check_energy_derivatives<3>(options, label);
        }
    }
}

TEST(SimplexEnergy, InvertedOrOverTheBoundIsInfinite) {
    SimplexEnergyOptions options;
    options.barrier.bound = 2.0;
    const SimplexEnergy<2> energy(options, {1.0});
    Mat<2> flipped = Mat<2>::Identity();
    flipped(1, 1) = -1.0;
    EXPECT_EQ(energy.value(0, vec<2>(flipped)), kInfinity);
    Mat<2> stretched = Mat<2>::Identity();
    stretched(0, 0) = 5.0;  // conformal distortion (5 + 1/5) / 2 = 2.6 > 2
    EXPECT_EQ(energy.value(0, vec<2>(stretched)), kInfinity);
    EXPECT_TRUE(std::isfinite(energy.value(0, vec<2>(Mat<2>::Identity()))));
}

TEST(SimplexEnergy, InvalidOptionsAreRejected) {
    SimplexEnergyOptions options;
    options.barrier.bound = 0.5;
    EXPECT_THROW(SimplexEnergy<2>(options, {1.0}), InvalidArgumentError);
    options = {};
    options.barrier_distortion = DistortionType::kArap;
    EXPECT_THROW(SimplexEnergy<2>(options, {1.0}), InvalidArgumentError);
    options = {};
    options.mapping_distortion = DistortionType::kDifference;
    EXPECT_THROW(SimplexEnergy<2>(options, {1.0, 1.0}, {Mat<2>::Identity()}), InvalidArgumentError);
    EXPECT_THROW(parse_distortion("conformall"), InvalidArgumentError);
    EXPECT_EQ(parse_distortion("symmetric-dirichlet"), DistortionType::kSymmetricDirichlet);
}

template <int D>
void check_max_step(const SimplexEnergyOptions& options) {
    std::mt19937 rng(5);
    std::normal_distribution<double> normal;
    const SimplexEnergy<D> energy(options, {1.0});
    int hit = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const Vec<D* D> a = vec<D>(random_positive_matrix<D>(rng));
        if (!std::isfinite(energy.value(0, a))) continue;
        Vec<D * D> da;
        for (int k = 0; k < D * D; ++k) da[k] = normal(rng);
        const double t = energy.max_step(0, a, da);
        if (!std::isfinite(t)) continue;
        ++hit;
        // Judged on the distortion: e^{s d} overflows before det A reaches 0.
        auto feasible = [&](double step) {
            return energy.barrier_distortion(unvec<D>(a + step * da)) < options.barrier.bound;
        };
        EXPECT_TRUE(feasible(0.999 * t)) << "trial " << trial;
        EXPECT_FALSE(feasible(1.001 * t)) << "trial " << trial;
    }
    EXPECT_GT(hit, 50);
}

TEST(SimplexEnergy, MaxStepIsWhereTheElementBecomesInfeasible) {
    SimplexEnergyOptions unbounded;
    check_max_step<2>(unbounded);
    check_max_step<3>(unbounded);
    SimplexEnergyOptions conformal_bound;
    conformal_bound.barrier.bound = 3.0;
    check_max_step<2>(conformal_bound);
    SimplexEnergyOptions volumetric_bound;
    volumetric_bound.barrier_distortion = DistortionType::kVolumetric;
    volumetric_bound.barrier.bound = 1.5;
    check_max_step<2>(volumetric_bound);
    check_max_step<3>(volumetric_bound);
}

}  // namespace
}  // namespace sa
