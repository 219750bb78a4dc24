#include <gtest/gtest.h>

#include "frontends/simplex_assembly/translation_gluing.h"
#include "geometry/maps/vertex_recovery.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/quality/map_quality.h"
#include "optim/errors.h"

namespace sa {
namespace {

// A smooth, non-affine, orientation-preserving map of the unit square / cube.
Eigen::MatrixXd bend(const Eigen::MatrixXd& rest) {
    Eigen::MatrixXd out = rest;
    for (Index v = 0; v < rest.rows(); ++v) {
        const double x = rest(v, 0), y = rest(v, 1);
        out(v, 0) = 1.5 * x + 0.2 * y * y + 3.0;
        out(v, 1) = y + 0.3 * x * x - 1.0;
    }
    return out;
}

template <int D>
void check_reproduces(const SimplicialMesh& mesh) {
    const RestFrames<D> frames = rest_frames<D>(mesh);
    const MeshTopology topology = mesh_topology(mesh, "generated");
    const Eigen::MatrixXd mapped = bend(mesh.vertices);
    const std::vector<Mat<D>> A = linear_parts<D>(mesh, frames, mapped);

    // Gluing from one known translation (simplex 0's centroid image) places every simplex.
    Vec<D> t0 = Vec<D>::Zero();
    for (int k = 0; k <= D; ++k) t0 += mapped.row(mesh.simplices(0, k)).transpose() / double(D + 1);
    const std::vector<Vec<D>> T =
        glue_translations<D>(mesh, topology, frames, A, {{0, t0}},
                             std::vector<Vec<D>>(mesh.num_simplices(), Vec<D>::Zero()));
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        for (int k = 0; k <= D; ++k) {
            const Vec<D> image = A[s] * frames.corner(s, k) + T[s];
            EXPECT_LT((image - mapped.row(mesh.simplices(s, k)).transpose()).norm(), 1e-12);
        }
    }
    // Recovery with the boundary fixed returns the map.
    std::vector<unsigned char> fixed = topology.boundary_vertex;
    Eigen::MatrixXd start = mapped;
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        if (!fixed[v]) start.row(v).setConstant(7.0);  // must not matter
    }
    const Eigen::MatrixXd recovered = recover_vertices<D>(mesh, frames, A, start, fixed);
    EXPECT_LT((recovered - mapped).cwiseAbs().maxCoeff(), 1e-11);
    // One fixed vertex is enough when the A_i assemble.
    std::vector<unsigned char> one(mesh.num_vertices(), 0);
    one[0] = 1;
    EXPECT_LT((recover_vertices<D>(mesh, frames, A, mapped, one) - mapped).cwiseAbs().maxCoeff(),
              1e-11);
    // None is not.
    EXPECT_THROW(recover_vertices<D>(mesh, frames, A, mapped,
                                     std::vector<unsigned char>(mesh.num_vertices(), 0)),
                 InvalidArgumentError);
    const MapQuality q = map_quality<D>(A, frames.volume);
    EXPECT_EQ(q.inverted, 0);
    EXPECT_GT(q.conformal.max, 1.0);
}

TEST(Recovery, GluingAndEquation6ReproduceAPiecewiseAffineMap2D) {
    check_reproduces<2>(grid_triangles(6, 5));
}
TEST(Recovery, GluingAndEquation6ReproduceAPiecewiseAffineMap3D) {
    check_reproduces<3>(grid_tetrahedra(3, 3, 2));
}

TEST(Recovery, SurfaceTrianglesInSpaceUseTheirOwnFrames) {
    SimplicialMesh mesh = grid_triangles(4, 4);
    Eigen::MatrixXd lifted(mesh.num_vertices(), 3);
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        // An isometric roll of the plane onto a cylinder: the developable map back is the grid.
        const double x = mesh.vertices(v, 0), y = mesh.vertices(v, 1);
        lifted.row(v) << std::sin(x), y, 1.0 - std::cos(x);
    }
    const Eigen::MatrixXd flat = mesh.vertices;
    mesh.vertices = lifted;
    const RestFrames<2> frames = rest_frames<2>(mesh);
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        EXPECT_GT(frames.edge_inverse[s].determinant(), 0.0);  // positively oriented frames
    }
    const std::vector<Mat<2>> A = linear_parts<2>(mesh, frames, flat);
    const MapQuality q = map_quality<2>(A, frames.volume);
    EXPECT_EQ(q.inverted, 0);
    EXPECT_LT(q.isometric.max, 1.01);  // chords of a gently rolled strip: nearly isometric
}

TEST(MeshTopology, CountsAndErrors) {
    const SimplicialMesh grid = grid_triangles(3, 2);
    const MeshTopology t = mesh_topology(grid, "grid");
    EXPECT_EQ(t.interior_facets.size(), 3u * 2 * 3 - 3 - 2);  // edges minus boundary edges
    EXPECT_EQ(t.boundary_facets.size(), 10u);
    EXPECT_EQ(t.edges.size(), 3u * 3 + 4u * 2 + 6u);
    Index components = 0;
    t.simplex_components(&components);
    EXPECT_EQ(components, 1);

    SimplicialMesh fan;  // three triangles on one edge: not manifold
    fan.vertices.resize(5, 3);
    fan.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1;
    fan.simplices.resize(3, 3);
    fan.simplices << 0, 1, 2, 1, 0, 3, 0, 1, 4;
    try {
        mesh_topology(fan, "fan.obj");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("fan.obj: the mesh is not manifold: edge (0, 1)"),
                  std::string::npos)
            << e.what();
    }
    SimplicialMesh flipped = fan;  // two triangles on one edge, same direction
    flipped.simplices.resize(2, 3);
    flipped.simplices << 0, 1, 2, 0, 1, 3;
    EXPECT_THROW(mesh_topology(flipped, "flipped.obj"), InputError);
}

// A bowtie and two boxes of tetrahedra touching at a corner are pinched there; a grid, a fan
// around one vertex and a closed sphere are not.
TEST(MeshTopology, PinchedVerticesAreFound) {
    SimplicialMesh bowtie;
    bowtie.vertices.resize(5, 2);
    bowtie.vertices << 0, 0, 1, 0, 0.5, 0.5, 0, 1, 1, 1;
    bowtie.simplices.resize(2, 3);
    bowtie.simplices << 0, 1, 2, 2, 4, 3;
    const MeshTopology bowtie_topology = mesh_topology(bowtie, "bowtie");
    EXPECT_EQ(pinched_vertices(bowtie, bowtie_topology), (std::vector<Index>{2}));
    try {
        require_no_pinched_vertex(bowtie, bowtie_topology, "bowtie.off", "needs a fan");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "bowtie.off: pinched at vertex 2: its triangles form 2 pieces that share no "
                  "edge through it (the only one); needs a fan");
    }

    SimplicialMesh boxes = grid_tetrahedra(1, 1, 1);  // the unit cube, and a copy at (1, 1, 1)
    const Index n = boxes.num_vertices();
    Eigen::MatrixXd vertices(2 * n, 3);
    vertices << boxes.vertices, boxes.vertices.rowwise() + Eigen::RowVector3d(1, 1, 1);
    Eigen::MatrixXi simplices(2 * boxes.num_simplices(), 4);
    simplices << boxes.simplices, boxes.simplices.array() + int(n);
    // The copy's corner at (1, 1, 1) is the cube's vertex at (1, 1, 1).
    Index far = -1, near = -1;
    for (Index v = 0; v < n; ++v) {
        if (boxes.vertices.row(v) == Eigen::RowVector3d(1, 1, 1)) far = v;
        if (boxes.vertices.row(v) == Eigen::RowVector3d(0, 0, 0)) near = v;
    }
    ASSERT_GE(far, 0);
    ASSERT_GE(near, 0);
    simplices = simplices.unaryExpr([&](int v) { return v == int(n + near) ? int(far) : v; });
    boxes.vertices = vertices;
    boxes.simplices = simplices;
    EXPECT_EQ(pinched_vertices(boxes, mesh_topology(boxes, "boxes")), (std::vector<Index>{far}));

    const SimplicialMesh grid = grid_triangles(3, 3);
    EXPECT_TRUE(pinched_vertices(grid, mesh_topology(grid, "grid")).empty());
    const SimplicialMesh sphere = sphere_triangles(2);
    EXPECT_TRUE(pinched_vertices(sphere, mesh_topology(sphere, "sphere")).empty());
    const SimplicialMesh cube = grid_tetrahedra(2, 2, 2);
    EXPECT_TRUE(pinched_vertices(cube, mesh_topology(cube, "cube")).empty());
}

TEST(SimplicialMesh, ValidationNamesTheProblem) {
    SimplicialMesh mesh = grid_triangles(2, 2);
    EXPECT_NO_THROW(validate_mesh(mesh, "grid"));
    mesh.simplices(3, 1) = 40;
    try {
        validate_mesh(mesh, "grid.off");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "grid.off: simplex 3 names vertex 40, outside [0, 9)");
    }
    mesh = grid_triangles(2, 2);
    mesh.vertices.row(4) = mesh.vertices.row(0);  // collapses triangles around vertex 4
    EXPECT_THROW(validate_mesh(mesh, "grid"), InputError);
}

}  // namespace
}  // namespace sa
