#include <gtest/gtest.h>

#include "energies/boundary_angle_energy.h"
#include "optim/derivative_check.h"

namespace sa {
namespace {

// A boundary vertex at the origin with a fan of K triangles whose neighbours lie on the unit circle
// at the given angles (degrees).
template <int K>
Vec<2 * K + 4> fan_positions(const std::array<double, K + 1>& degrees) {
    Vec<2 * K + 4> x;
    x.template head<2>() = Vec<2>(0.0, 0.0);
    for (int m = 0; m <= K; ++m) {
        const double t = degrees[m] * M_PI / 180.0;
        x.template segment<2>(2 + 2 * m) = Vec<2>(std::cos(t), std::sin(t));
    }
    return x;
}

Vec<10> fan_positions() {
    return fan_positions<3>({0.0, 60.0, 120.0, 200.0});
}

TEST(BoundaryAngleEnergy, VertexFormIsOneOverTheAngleGap) {
    EXPECT_NEAR(BoundaryAngleVertexEnergy<3>{}.value(0, fan_positions()),
                1.0 / (2.0 * M_PI - 200.0 * M_PI / 180.0), 1e-12);
    const BoundaryAngleVertexEnergy<4> four;
    EXPECT_NEAR(four.value(0, fan_positions<4>({0.0, 100.0, 200.0, 300.0, 359.0})),
                1.0 / (M_PI / 180.0), 1e-9);
    EXPECT_EQ(four.value(0, fan_positions<4>({0.0, 100.0, 200.0, 300.0, 361.0})), kInfinity);
}

TEST(BoundaryAngleEnergy, DerivativesMatchFiniteDifferences) {
    Vec<10> x = fan_positions();
    x.head<2>() = Vec<2>(0.1, -0.05);
    EXPECT_TRUE(check_derivatives(BoundaryAngleVertexEnergy<3>{}, 0, x).passes(1e-6));

    // The same fan as linear maps of three rest triangles with edges e0, e1 at v.
    BoundaryAngleEnergy<2> energy;
    std::array<Mat<2>, 2> edges;
    edges[0] << 1.0, 0.5, 0.0, 0.9;
    edges[1] << 0.5, -0.4, 0.9, 0.8;
    energy.edges.push_back(edges);
    Vec<8> a;
    a << 1.1, 0.2, -0.1, 0.9, 0.8, 0.1, 0.3, 1.2;
    EXPECT_TRUE(check_derivatives(energy, 0, a).passes(1e-6));
}

TEST(BoundaryAngleEnergy, LinearFormAgreesWithVertexForm) {
    // Triangle k of the vertex fan maps rest edges E_k to (p_{k+1} - v, p_{k+2} - v): A_k = P_k
    // E_k^-1.
    const Vec<10> x = fan_positions();
    BoundaryAngleEnergy<3> linear;
    std::array<Mat<2>, 3> edges;
    Vec<12> a;
    for (int k = 0; k < 3; ++k) {
        edges[k] << 1.0, 0.2 * k, 0.1, 1.0;  // arbitrary rest edges
        Mat<2> images;
        images.col(0) = x.segment<2>(2 + 2 * k) - x.head<2>();
        images.col(1) = x.segment<2>(4 + 2 * k) - x.head<2>();
        const Mat<2> A = images * edges[k].inverse();
        a.segment<4>(4 * k) = Eigen::Map<const Vec<4>>(A.data());
    }
    linear.edges.push_back(edges);
    EXPECT_NEAR(linear.value(0, a), BoundaryAngleVertexEnergy<3>{}.value(0, x), 1e-12);
}

}  // namespace
}  // namespace sa
