#include "frontends/polycube/polycube_label_transfer.h"

#include <gtest/gtest.h>

#include <numeric>
#include <random>

#include "frontends/polycube/polycube_labeling.h"
#include "optim/errors.h"
#include "tests/fixtures/polycube_fixtures.h"

namespace sa {
namespace {

struct Case {
    SimplicialMesh mesh;
    TetBoundary boundary;
    std::vector<int> labels;
    SimplicialMesh surface;  ///< the boundary, vertices shuffled and rounded, windings reversed
    std::vector<int> surface_labels;
};

Case make_case() {
    Case c;
    c.mesh = testing::bent(testing::voxel_tetrahedra(testing::l_shape(), 2), 0.03);
    c.boundary = tet_boundary(c.mesh, mesh_topology(c.mesh, "L"));
    c.labels = closest_axis_labels(c.boundary, c.mesh.vertices);
    std::vector<Index> on;
    for (Index v = 0; v < c.mesh.num_vertices(); ++v) {
        if (c.boundary.on_boundary[v]) on.push_back(v);
    }
    std::mt19937 random(7);
    std::shuffle(on.begin(), on.end(), random);
    std::vector<Index> new_index(c.mesh.num_vertices(), -1);
    c.surface.vertices.resize(Index(on.size()), 3);
    for (std::size_t i = 0; i < on.size(); ++i) {
        new_index[on[i]] = Index(i);
        // Rounded to 6 significant digits, as a file with fewer digits would give them.
        for (int k = 0; k < 3; ++k) {
            c.surface.vertices(Index(i), k) =
                std::stod(std::to_string(float(c.mesh.vertices(on[i], k))).substr(0, 8));
        }
    }
    const Index nb = c.boundary.size();
    std::vector<Index> order(nb);
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), random);
    c.surface.simplices.resize(nb, 3);
    for (Index f = 0; f < nb; ++f) {
        const Index b = order[f];
        c.surface.simplices.row(f) << new_index[c.boundary.triangles(b, 0)],
            new_index[c.boundary.triangles(b, 2)], new_index[c.boundary.triangles(b, 1)];
        c.surface_labels.push_back(c.labels[b]);
    }
    return c;
}

TEST(PolycubeLabelTransfer, SurfaceLabelsLandOnTheirTetFacets) {
    const Case c = make_case();
    EXPECT_EQ(transfer_surface_labels(c.mesh, c.boundary, c.surface, c.surface_labels, "s.obj"),
              c.labels);
}

TEST(PolycubeLabelTransfer, AMismatchedSurfaceIsRejected) {
    const Case c = make_case();
    auto message = [&](const SimplicialMesh& surface, const std::vector<int>& labels) {
        try {
            transfer_surface_labels(c.mesh, c.boundary, surface, labels, "s.obj");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    SimplicialMesh moved = c.surface;
    moved.vertices(3, 0) += 0.2;
    EXPECT_NE(message(moved, c.surface_labels).find("s.obj: surface vertex 3 is not at a boundary"),
              std::string::npos);
    SimplicialMesh fewer = c.surface;
    fewer.simplices.conservativeResize(fewer.simplices.rows() - 1, 3);
    std::vector<int> fewer_labels(c.surface_labels.begin(), c.surface_labels.end() - 1);
    EXPECT_NE(message(fewer, fewer_labels).find("has no triangle at the boundary triangle"),
              std::string::npos);
    SimplicialMesh other = c.surface;
    std::swap(other.simplices(0, 0), other.simplices(1, 0));
    EXPECT_NE(message(other, c.surface_labels).find("is not a boundary triangle"),
              std::string::npos);
    std::vector<int> short_labels(c.surface_labels.begin(), c.surface_labels.end() - 2);
    EXPECT_NE(message(c.surface, short_labels).find("labels for"), std::string::npos);
}

}  // namespace
}  // namespace sa
