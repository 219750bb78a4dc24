#include "frontends/seamless/integrable_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "frontends/seamless/cut_graph.h"
#include "frontends/seamless/frame_field.h"
#include "geometry/mesh/mesh_generators.h"

namespace sa {
namespace {

// The torus's angle map (i / nu, j / nv) as a field, each frame turned by up to 0.15 rad and
// stretched by up to 20% along its axes: far from integrable, no singularities.
struct NoisyTorus {
    SimplicialMesh mesh = torus_triangles(24, 12);
    MeshTopology topology = mesh_topology(mesh, "torus");
    RestFrames<2> frames = rest_frames<2>(mesh);
    std::vector<Mat<2>> phi;
    std::vector<int> matching;

    NoisyTorus() {
        const int nu = 24, nv = 12;
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> angle(-0.15, 0.15), stretch(0.8, 1.2);
        for (Index f = 0; f < mesh.num_simplices(); ++f) {
            Eigen::Matrix<double, 2, 3> uv;
            for (int k = 0; k < 3; ++k) {
                const Index v = mesh.simplices(f, k);
                uv.col(k) << double(v % nu) / nu, double(v / nu) / nv;
                for (int c = 0; k > 0 && c < 2; ++c) uv(c, k) -= std::round(uv(c, k) - uv(c, 0));
            }
            const double a = angle(rng);
            Mat<2> R;
            R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
            // Drawn in separate statements: the order in which a call's arguments are evaluated
            // is unspecified (gcc and clang differ); this is the order the values below came from.
            const double stretch_v = stretch(rng);
            const double stretch_u = stretch(rng);
            phi.push_back(Eigen::Vector2d(stretch_u, stretch_v).asDiagonal() *
                          linear_part<2>(frames, f, uv) * R);
        }
        matching = cross_field_matchings(mesh, topology, frame_cross_directions(frames, phi));
    }
};

// The integrability step before it ran on the engine (its own copy of the lambda schedule, at
// commit 3f122a2) gave these numbers on this field; the engine's schedule must give the same.
TEST(IntegrableField, SameFieldAsBeforeOnANoisyTorus) {
    const NoisyTorus t;
    const IntegrableField r = integrable_field(t.mesh, t.topology, t.frames, t.phi, t.matching);
    EXPECT_TRUE(r.assembled);
    EXPECT_LT(r.assembly, 1e-12);
    // The fourth step changes the energy at round-off (2e-11) and the matrices by about 1e-9:
    // whether the solver takes it depends on the machine's floating point (BLAS kernels differ
    // between CPUs), so 3 or 4 steps, and the field is compared at that tolerance.
    EXPECT_GE(r.newton.num_steps(), 3);
    EXPECT_LE(r.newton.num_steps(), 4);
    const double energies[] = {42460.333984213154, 21972.796906479492, 22347.61080256796,
                               22347.617887927736, 22347.617887927718};
    ASSERT_GE(r.newton.iterations.size(), 4u);
    ASSERT_LE(r.newton.iterations.size(), std::size(energies));
    for (std::size_t k = 0; k < r.newton.iterations.size(); ++k)
        EXPECT_NEAR(r.newton.iterations[k].energy, energies[k], 1e-10 * energies[k]) << k;
    double checksum = 0.0;
    for (std::size_t f = 0; f < r.matrices.size(); ++f)
        checksum += double(f % 7 + 1) * (r.matrices[f](0, 0) + 2.0 * r.matrices[f](1, 0) +
                                         3.0 * r.matrices[f](0, 1) + 4.0 * r.matrices[f](1, 1));
    EXPECT_NEAR(checksum, 3754.2220467470988, 1e-5);
    Mat<2> first;
    first << 0.11099075937659289, 0.0027129716290447124, -0.0075306015838555495, 0.4349532607304934;
    EXPECT_LT((r.matrices[0] - first).norm(), 1e-8);
}

}  // namespace
}  // namespace sa
