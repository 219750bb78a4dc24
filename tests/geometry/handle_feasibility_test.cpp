#include "geometry/quality/handle_feasibility.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>

#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/mesh_topology.h"

namespace sa {
namespace {

/// Every boundary vertex of a 3 x 3 x 3 tet grid as a handle at its rest position.
struct FixedBox {
    SimplicialMesh mesh = grid_tetrahedra(3, 3, 3);
    std::vector<Index> handles;
    Eigen::MatrixXd targets;
    FixedBox() {
        const MeshTopology t = mesh_topology(mesh, "box");
        for (Index v = 0; v < mesh.num_vertices(); ++v) {
            if (t.boundary_vertex[v]) handles.push_back(v);
        }
        targets.resize(handles.size(), 3);
        for (std::size_t k = 0; k < handles.size(); ++k)
            targets.row(k) = mesh.vertices.row(handles[k]);
    }
    Index row(Index vertex) const {
        return Index(std::find(handles.begin(), handles.end(), vertex) - handles.begin());
    }
    /// A simplex whose vertices are all handles.
    Index fixed_simplex() const {
        for (Index s = 0; s < mesh.num_simplices(); ++s) {
            bool all = true;
            for (int k = 0; k < 4; ++k)
                all = all && row(mesh.simplices(s, k)) < Index(handles.size());
            if (all) return s;
        }
        return -1;
    }
};

TEST(HandleFeasibility, AFixedBoundaryAtRestIsFeasible) {
    const FixedBox box;
    const HandleFeasibility f = check_handle_feasibility(box.mesh, box.handles, box.targets, 1e-9);
    EXPECT_TRUE(f.feasible()) << f.describe();
    EXPECT_GT(f.fixed_simplices, 0);
}

TEST(HandleFeasibility, FindsAFixedSimplexMirroredAndOneFlattened) {
    FixedBox box;
    const Index s = box.fixed_simplex();
    ASSERT_GE(s, 0);
    // Mirror the whole target set through a plane: every fixed simplex is inverted.
    Eigen::MatrixXd mirrored = box.targets;
    mirrored.col(0) *= -1.0;
    HandleFeasibility f = check_handle_feasibility(box.mesh, box.handles, mirrored, 1e-9);
    EXPECT_EQ(Index(f.inverted.size()), f.fixed_simplices);
    EXPECT_TRUE(f.flat.empty());
    EXPECT_NE(f.describe().find(std::to_string(f.inverted.size()) + " are inverted"),
              std::string::npos)
        << f.describe();

    // Flatten one fixed simplex: its first vertex onto the plane of the other three. That vertex
    // is a corner of other fixed simplices, which may invert: only `s` must be flat.
    Eigen::MatrixXd flat = box.targets;
    const Eigen::Vector3d a = box.mesh.vertices.row(box.mesh.simplices(s, 1)),
                          b = box.mesh.vertices.row(box.mesh.simplices(s, 2)),
                          c = box.mesh.vertices.row(box.mesh.simplices(s, 3));
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    const Index r = box.row(box.mesh.simplices(s, 0));
    const Eigen::Vector3d p = flat.row(r).transpose();
    flat.row(r) = (p - n * n.dot(p - a)).transpose();
    f = check_handle_feasibility(box.mesh, box.handles, flat, 1e-9);
    EXPECT_NE(std::find(f.flat.begin(), f.flat.end(), s), f.flat.end()) << f.describe();
    EXPECT_FALSE(f.feasible());
}

TEST(HandleFeasibility, DoesNotDependOnScale) {
    FixedBox box;
    Eigen::MatrixXd mirrored = box.targets;
    mirrored.col(2) *= -1.0;
    const HandleFeasibility f = check_handle_feasibility(box.mesh, box.handles, mirrored, 1e-9);
    for (double scale : {1e-8, 1e8}) {
        SimplicialMesh scaled = box.mesh;
        scaled.vertices *= 1.0 / scale;
        const HandleFeasibility g =
            check_handle_feasibility(scaled, box.handles, mirrored * scale, 1e-9 * scale);
        EXPECT_EQ(g.inverted, f.inverted);
        EXPECT_EQ(g.flat, f.flat);
        EXPECT_EQ(g.fixed_simplices, f.fixed_simplices);
    }
}

TEST(HandleFeasibility, FindsAHandleFixedTwiceAtDifferentPlaces) {
    FixedBox box;
    std::vector<Index> handles = box.handles;
    Eigen::MatrixXd targets(box.targets.rows() + 2, 3);
    targets << box.targets, box.targets.row(4), box.targets.row(7);
    handles.push_back(box.handles[4]);  // the same place: fine
    handles.push_back(box.handles[7]);
    targets(targets.rows() - 1, 1) += 0.5;  // another place
    const HandleFeasibility f = check_handle_feasibility(box.mesh, handles, targets, 1e-9);
    ASSERT_EQ(f.conflicts.size(), 1u) << f.describe();
    EXPECT_EQ(f.conflicts[0].vertex, box.handles[7]);
    EXPECT_NE(f.describe().find("fixed twice"), std::string::npos);
}

TEST(HandleFeasibility, FindsARestEdgeCollapsedByItsHandles) {
    // Triangles of a surface mapped to the plane: an edge between two boundary handles whose
    // targets coincide.
    SimplicialMesh mesh = grid_triangles(4, 4);
    Eigen::MatrixXd lifted(mesh.num_vertices(), 3);
    lifted << mesh.vertices, 0.1 * mesh.vertices.col(0).array().square().matrix();
    mesh.vertices = lifted;
    const std::vector<Index> handles = {0, 1, 2};  // the first row: edges 0-1 and 1-2
    Eigen::MatrixXd targets(3, 2);
    targets << 0.0, 0.0, 0.25, 0.0, 0.25, 0.0;
    const HandleFeasibility f = check_handle_feasibility(mesh, handles, targets, 1e-9);
    ASSERT_EQ(f.collapsed_edges.size(), 1u) << f.describe();
    EXPECT_EQ(f.collapsed_edges[0], (std::array<Index, 2>{1, 2}));
    EXPECT_EQ(f.fixed_simplices, 0);
}

TEST(HandleFeasibility, SurfaceTrianglesArePositiveAtRest) {
    // A lifted grid mapped to the plane with every vertex a handle: its own layout is feasible,
    // the mirrored layout is inverted everywhere.
    SimplicialMesh mesh = grid_triangles(3, 3);
    const Eigen::MatrixXd layout = mesh.vertices;
    Eigen::MatrixXd lifted(mesh.num_vertices(), 3);
    lifted << mesh.vertices, Eigen::VectorXd::Constant(mesh.num_vertices(), 2.0);
    mesh.vertices = lifted;
    std::vector<Index> all(mesh.num_vertices());
    for (Index v = 0; v < mesh.num_vertices(); ++v) all[v] = v;
    EXPECT_TRUE(check_handle_feasibility(mesh, all, layout, 1e-9).feasible());
    Eigen::MatrixXd mirrored = layout;
    mirrored.col(1) *= -1.0;
    const HandleFeasibility f = check_handle_feasibility(mesh, all, mirrored, 1e-9);
    EXPECT_EQ(Index(f.inverted.size()), mesh.num_simplices());
}

/// A disk fanned from one interior vertex (the last) to `boundary`'s points, in their order
/// (counterclockwise at rest); the boundary vertices are the handles, at `boundary`.
struct Fan {
    SimplicialMesh mesh;
    std::vector<Index> handles;
    Eigen::MatrixXd targets;
    explicit Fan(const Eigen::MatrixXd& boundary) {
        const Index n = boundary.rows();
        mesh.vertices.resize(n + 1, 2);
        for (Index k = 0; k < n; ++k) {
            const double t = 2.0 * M_PI * double(k) / double(n);
            mesh.vertices.row(k) << std::cos(t), std::sin(t);
        }
        mesh.vertices.row(n) << 0.0, 0.0;
        mesh.simplices.resize(n, 3);
        for (Index k = 0; k < n; ++k) mesh.simplices.row(k) << k, (k + 1) % n, n;
        for (Index k = 0; k < n; ++k) handles.push_back(k);
        targets = boundary;
    }
    HandleFeasibility check() const {
        const MeshTopology topology = mesh_topology(mesh, "fan");
        return check_handle_feasibility(mesh, handles, targets, 1e-9, &topology);
    }
};

Eigen::MatrixXd curve(Index n, const std::function<Eigen::RowVector2d(double)>& at) {
    Eigen::MatrixXd points(n, 2);
    for (Index k = 0; k < n; ++k) points.row(k) = at(2.0 * M_PI * double(k) / double(n));
    return points;
}

TEST(HandleFeasibility, AFixedBoundaryMustEncloseAPositiveArea) {
    const auto circle = [](double t) { return Eigen::RowVector2d(std::cos(t), std::sin(t)); };
    const Fan disk(curve(24, circle));
    const HandleFeasibility ok = disk.check();
    EXPECT_TRUE(ok.feasible()) << ok.describe();
    EXPECT_EQ(ok.fixed_simplices, 0);  // every triangle has the free centre

    // The boundary mirrored: no fixed triangle says so, the enclosed area does.
    Fan mirrored = disk;
    mirrored.targets.col(0) *= -1.0;
    const HandleFeasibility f = mirrored.check();
    ASSERT_EQ(f.enclosing.size(), 1u) << f.describe();
    EXPECT_TRUE(f.inverted.empty());
    EXPECT_NEAR(f.enclosing[0].volume, -24 * 0.5 * std::sin(2.0 * M_PI / 24), 1e-12);
    EXPECT_EQ(f.enclosing[0].simplices, 24);
    EXPECT_NE(f.describe().find("encloses a signed area"), std::string::npos) << f.describe();

    // Without the topology, or with a boundary vertex free, nothing is decided.
    EXPECT_TRUE(check_handle_feasibility(mirrored.mesh, mirrored.handles, mirrored.targets, 1e-9)
                    .feasible());
    Fan open = mirrored;
    open.handles.pop_back();
    open.targets.conservativeResize(open.targets.rows() - 1, 2);
    EXPECT_TRUE(open.check().feasible());
}

TEST(HandleFeasibility, AFixedDiskBoundaryMustTurnOnce) {
    // A figure eight with a larger right lobe: positive area, turning number 0.
    const auto eight = [](double t) {
        return Eigen::RowVector2d(std::sin(t), std::sin(2.0 * t) * (1.0 + 0.5 * std::sin(t)));
    };
    Eigen::MatrixXd boundary = curve(40, eight);
    double area = 0.0;
    for (Index k = 0; k < boundary.rows(); ++k) {
        const Eigen::RowVector2d a = boundary.row(k), b = boundary.row((k + 1) % boundary.rows());
        area += 0.5 * (a.x() * b.y() - a.y() * b.x());
    }
    if (area < 0.0) boundary = boundary.colwise().reverse().eval();
    const HandleFeasibility f = Fan(boundary).check();
    ASSERT_EQ(f.enclosing.size(), 1u) << f.describe();
    EXPECT_GT(f.enclosing[0].volume, 0.0);
    ASSERT_TRUE(f.enclosing[0].turning_measured);
    EXPECT_EQ(f.enclosing[0].turning, 0);
    EXPECT_EQ(f.enclosing[0].euler, 1);
    EXPECT_NE(f.describe().find("turn 0 times"), std::string::npos) << f.describe();

    // A boundary that winds twice turns twice: a disk may cover itself (a self-overlapping
    // boundary is not excluded by this test), so it is not called infeasible here.
    const auto twice = [](double t) -> Eigen::RowVector2d {
        return Eigen::RowVector2d(std::cos(2.0 * t), std::sin(2.0 * t)) * (1.0 + 0.1 * std::cos(t));
    };
    const HandleFeasibility g = Fan(curve(41, twice)).check();
    EXPECT_TRUE(g.feasible()) << g.describe();
}

TEST(HandleFeasibility, AFixedBoundaryMustEncloseAPositiveVolume) {
    // An octahedron fanned from its free centre: no tetrahedron has four handles.
    SimplicialMesh mesh;
    mesh.vertices.resize(7, 3);
    mesh.vertices << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0;
    const int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                             {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    mesh.simplices.resize(8, 4);
    for (int f = 0; f < 8; ++f) mesh.simplices.row(f) << faces[f][0], faces[f][1], faces[f][2], 6;
    const MeshTopology topology = mesh_topology(mesh, "octahedron");
    const std::vector<Index> handles = {0, 1, 2, 3, 4, 5};
    const Eigen::MatrixXd rest = mesh.vertices.topRows(6);
    const HandleFeasibility ok = check_handle_feasibility(mesh, handles, rest, 1e-9, &topology);
    EXPECT_TRUE(ok.feasible()) << ok.describe();
    Eigen::MatrixXd mirrored = rest;
    mirrored.col(2) *= -1.0;
    const HandleFeasibility f = check_handle_feasibility(mesh, handles, mirrored, 1e-9, &topology);
    EXPECT_EQ(f.fixed_simplices, 0);
    ASSERT_EQ(f.enclosing.size(), 1u) << f.describe();
    EXPECT_NEAR(f.enclosing[0].volume, -4.0 / 3.0, 1e-12);
    EXPECT_FALSE(f.enclosing[0].turning_measured);
    EXPECT_NE(f.describe().find("encloses a signed volume of -1.33333"), std::string::npos)
        << f.describe();
}

}  // namespace
}  // namespace sa
