// r-SA's Omega_s follows loops that generate the mesh's first homology
// (frontends/simplex_assembly/detail/assembly_problem.h). Linear parts that agree across every
// shared facet (Eq. 7) but integrate around a hole to a map that does not close, the derivative of
// (log r, theta) around an annulus' hole or a ring's, must not count as assembled: with the
// linear parts held, no choice of the translations brings E~_assembly near zero. Those of a map
// that closes assemble exactly. (Before the loops, Omega_s was empty without handles and the
// multivalued field had E~ = 0.)
#include "frontends/simplex_assembly/detail/assembly_problem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/rest_frames.h"
#include "tests/fixtures/polycube_fixtures.h"

namespace sa {
namespace {

template <int D>
using PointMap = std::function<Vec<D>(const Vec<D>& point, const Vec<D>& branch)>;

// (log r, theta, z...) about the axis through `centre`, theta on the branch nearest `branch`'s.
template <int D>
PointMap<D> logarithm(const Vec<D>& centre) {
    return [centre](const Vec<D>& p, const Vec<D>& branch) {
        const double reference = std::atan2(branch[1] - centre[1], branch[0] - centre[0]);
        const double angle = std::atan2(p[1] - centre[1], p[0] - centre[0]);
        Vec<D> image = p;
        image[0] = std::log(std::hypot(p[0] - centre[0], p[1] - centre[1]));
        image[1] = reference + std::remainder(angle - reference, 2.0 * M_PI);
        return image;
    };
}

template <int D>
PointMap<D> shear() {
    return [](const Vec<D>& p, const Vec<D>&) {
        Vec<D> image = p;
        image[0] += 0.5 * p[1];
        return image;
    };
}

// E~_assembly of r-SA after minimizing over the translations, the linear parts held at those of
// `map` applied to each simplex's corners (each on the branch of its first corner).
template <int D>
double assembly_left(const SimplicialMesh& mesh, const PointMap<D>& map) {
    const MeshTopology topology = mesh_topology(mesh, "generated");
    const RestFrames<D> frames = rest_frames<D>(mesh);
    AssemblyInput<D> in;
    in.mesh = &mesh;
    in.topology = &topology;
    in.frames = &frames;
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        const Vec<D> first = mesh.vertices.row(mesh.simplices(s, 0)).transpose();
        Eigen::Matrix<double, D, D + 1> mapped;
        for (int k = 0; k <= D; ++k)
            mapped.col(k) = map(mesh.vertices.row(mesh.simplices(s, k)).transpose(), first);
        in.start_linear.push_back(linear_part<D>(frames, s, mapped));
        in.start_translation.push_back(mapped.rowwise().mean());  // frame origin: the centroid
    }
    in.reference_linear = in.start_linear;
    in.anchored_simplices = {0};
    SimplexAssemblyOptions options;
    options.variant = Variant::kReduced;
    AssemblyProblem<D> assembly(in, options);
    SimplexAssemblyEngine<D>& engine = assembly.engine();
    for (Index s = 0; s < mesh.num_simplices(); ++s)
        for (Index v : engine.linear_variables(s)) engine.problem().set_fixed(v);
    engine.run(AssemblyEngineOptions{});
    return engine.assembly_energy();
}

// A 2D annulus, radii 1 to 2: 4 rings of 24 sectors.
SimplicialMesh annulus() {
    const int rings = 4, sectors = 24;
    SimplicialMesh mesh;
    mesh.vertices.resize((rings + 1) * sectors, 2);
    auto id = [&](int i, int j) { return i * sectors + j % sectors; };
    for (int i = 0; i <= rings; ++i) {
        for (int j = 0; j < sectors; ++j) {
            const double r = 1.0 + double(i) / rings, a = 2.0 * M_PI * j / sectors;
            mesh.vertices.row(id(i, j)) << r * std::cos(a), r * std::sin(a);
        }
    }
    mesh.simplices.resize(2 * rings * sectors, 3);
    Index t = 0;
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < sectors; ++j) {
            mesh.simplices.row(t++) << id(i, j), id(i, j + 1), id(i + 1, j + 1);
            mesh.simplices.row(t++) << id(i, j), id(i + 1, j + 1), id(i + 1, j);
        }
    }
    return mesh;
}

TEST(AssemblyLoops, AFieldThatDoesNotCloseAroundAHoleIsNotAssembled) {
    const SimplicialMesh mesh = annulus();
    EXPECT_GT(assembly_left<2>(mesh, logarithm<2>(Vec<2>::Zero())), 1e-3);
    EXPECT_LT(assembly_left<2>(mesh, shear<2>()), 1e-12);
}

TEST(AssemblyLoops, AFieldThatDoesNotCloseAroundAHandleIsNotAssembled) {
    const SimplicialMesh ring = testing::voxel_tetrahedra(testing::ring(), 2);
    EXPECT_GT(assembly_left<3>(ring, logarithm<3>(Vec<3>(1.5, 1.5, 0.0))), 1e-3);
    EXPECT_LT(assembly_left<3>(ring, shear<3>()), 1e-12);
}

}  // namespace
}  // namespace sa
