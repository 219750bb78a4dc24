#include "geometry/handle_feasibility.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>

#include "geometry/mesh_generators.h"
#include "geometry/mesh_topology.h"

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

}  // namespace
}  // namespace sa
