#include "frontends/polycube/polycube_labeling.h"

#include <gtest/gtest.h>

#include "optim/errors.h"
#include "tests/fixtures/polycube_fixtures.h"

namespace sa {
namespace {

using testing::bent;
using testing::l_shape;
using testing::voxel_tetrahedra;

struct Labelled {
    SimplicialMesh mesh;
    MeshTopology topology;
    TetBoundary boundary;
    std::vector<int> labels;
};

Labelled closest(const SimplicialMesh& mesh) {
    Labelled l{mesh, mesh_topology(mesh, "test"), {}, {}};
    l.boundary = tet_boundary(l.mesh, l.topology);
    l.labels = closest_axis_labels(l.boundary, l.mesh.vertices);
    return l;
}

// A triangular prism (a roof) along z, its two roof faces steeper than 45 degrees: their closest
// labels are -X and +X, and they meet at the ridge.
SimplicialMesh roof() {
    SimplicialMesh mesh;
    mesh.vertices.resize(6, 3);
    mesh.vertices << 0, 0, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1, 2, 0, 1, 1, 3, 1;
    mesh.simplices.resize(3, 4);
    mesh.simplices << 0, 1, 2, 3, 1, 2, 3, 4, 2, 3, 4, 5;
    for (Index t = 0; t < 3; ++t) {
        if (tet_orientation(mesh, t) < 0) mesh.simplices.row(t).segment<2>(1).reverseInPlace();
    }
    return mesh;
}

TEST(PolycubeLabeling, LabelNamesAndDirections) {
    EXPECT_EQ(label_name(0), "+X");
    EXPECT_EQ(label_name(3), "-Y");
    EXPECT_EQ(label_name(5), "-Z");
    EXPECT_EQ(label_direction(3), Eigen::Vector3d(0, -1, 0));
    EXPECT_EQ(make_label(2, -1), 5);
    EXPECT_EQ(label_axis(4), 2);
    EXPECT_EQ(label_sign(1), -1);
}

TEST(PolycubeLabeling, BoundaryTrianglesPointOutwardAndMatchTetFacets) {
    const Labelled l = closest(voxel_tetrahedra({{0, 0, 0}}, 2));
    EXPECT_EQ(l.boundary.size(), 6 * 2 * 4);  // six faces of 2 x 2 squares of two triangles
    const Eigen::MatrixXd area = boundary_area_vectors(l.boundary, l.mesh.vertices);
    Eigen::Vector3d centroid = l.mesh.vertices.colwise().mean().transpose();
    double total = 0.0;
    for (Index b = 0; b < l.boundary.size(); ++b) {
        const Eigen::Vector3d at = l.mesh.vertices.row(l.boundary.triangles(b, 0)).transpose();
        EXPECT_GT(area.row(b).dot((at - centroid).transpose()), 0.0) << b;
        EXPECT_EQ(l.boundary.of_tet_facet[l.boundary.tet_facet[b]], b);
        total += area.row(b).norm();
        for (const Index n : l.boundary.adjacent[b]) EXPECT_GE(n, 0);
    }
    EXPECT_NEAR(total, 6.0, 1e-12);
}

TEST(PolycubeLabeling, ClosestAxisGivesTheSixFacesOfABox) {
    const Labelled l = closest(bent(voxel_tetrahedra({{0, 0, 0}}, 3), 0.05));
    const PolycubeCharts charts = polycube_charts(l.boundary, l.mesh.vertices, l.labels);
    ASSERT_EQ(charts.size(), 6);
    std::vector<int> seen(6, 0);
    for (int c = 0; c < 6; ++c) {
        ++seen[charts.label[c]];
        EXPECT_EQ(charts.neighbours[c].size(), 4u);
        EXPECT_EQ(charts.members[c].size(), 18u);
        EXPECT_GT(charts.aligned_area[c], 0.9 * charts.area[c]);
    }
    EXPECT_EQ(seen, std::vector<int>(6, 1));
    EXPECT_NO_THROW(validate_polycube_labels(l.mesh, l.boundary, l.labels, "box"));
}

TEST(PolycubeLabeling, ClosestAxisOnAnLShapeGivesEightCharts) {
    const Labelled l = closest(voxel_tetrahedra(l_shape(), 2));
    const PolycubeCharts charts = polycube_charts(l.boundary, l.mesh.vertices, l.labels);
    EXPECT_EQ(charts.size(), 8);  // +Z, -Z, and six side faces (two of them at the inner corner)
    EXPECT_NO_THROW(validate_polycube_labels(l.mesh, l.boundary, l.labels, "L"));
}

// The file's parity is read in both conventions; the side always comes from the geometry.
TEST(PolycubeLabeling, FileLabelsInEitherSignConventionGiveTheSameLabels) {
    const Labelled l = closest(bent(voxel_tetrahedra(l_shape(), 2), 0.03));
    for (const FlagSign sign : {FlagSign::kOutward, FlagSign::kInward}) {
        const std::vector<int> flags =
            facet_flags(l.boundary, l.mesh.num_simplices(), l.labels, sign);
        for (std::size_t f = 0; f < flags.size(); ++f) {
            EXPECT_EQ(flags[f] == kNoLabel, l.boundary.of_tet_facet[f] < 0);
        }
        const std::vector<int> raw =
            boundary_labels_from_flags(l.boundary, l.mesh.num_simplices(), flags, "L.flags");
        LabelConvention convention;
        EXPECT_EQ(labels_from_file_axes(l.mesh, l.boundary, raw, "L.flags", &convention), l.labels);
        const Index n = l.boundary.size();
        EXPECT_EQ(convention.outward, sign == FlagSign::kOutward ? n : 0);
        EXPECT_EQ(convention.inward, sign == FlagSign::kInward ? n : 0);
        EXPECT_EQ(convention.negative_tets, 0);
        EXPECT_NE(convention.describe().find(sign == FlagSign::kOutward ? "outward" : "inward"),
                  std::string::npos);
    }
}

TEST(PolycubeLabeling, NegativelyOrientedTetsAreReported) {
    const Labelled l = closest(testing::reversed(voxel_tetrahedra({{0, 0, 0}}, 1)));
    // Their facet winding points inwards; the outward normals are still found.
    const PolycubeCharts charts = polycube_charts(l.boundary, l.mesh.vertices, l.labels);
    EXPECT_EQ(charts.size(), 6);
    const std::vector<int> flags =
        facet_flags(l.boundary, l.mesh.num_simplices(), l.labels, FlagSign::kInward);
    LabelConvention convention;
    labels_from_file_axes(l.mesh, l.boundary,
                          boundary_labels_from_flags(l.boundary, 6, flags, "cube.flags"),
                          "cube.flags", &convention);
    EXPECT_EQ(convention.negative_tets, 6);
    EXPECT_NE(convention.describe().find("negatively oriented"), std::string::npos);
}

TEST(PolycubeLabeling, BadFlagsAreRejectedNamingTheFacet) {
    const Labelled l = closest(voxel_tetrahedra({{0, 0, 0}}, 1));
    const Index nt = l.mesh.num_simplices();
    std::vector<int> flags = facet_flags(l.boundary, nt, l.labels);
    auto message = [&](const std::vector<int>& f) {
        try {
            boundary_labels_from_flags(l.boundary, nt, f, "cube.flags");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    std::vector<int> shorter(flags.begin(), flags.end() - 1);
    EXPECT_NE(message(shorter).find("expected 24"), std::string::npos) << message(shorter);
    const Index interior =
        Index(std::find(l.boundary.of_tet_facet.begin(), l.boundary.of_tet_facet.end(), -1) -
              l.boundary.of_tet_facet.begin());
    std::vector<int> labelled_interior = flags;
    labelled_interior[interior] = 2;
    EXPECT_NE(message(labelled_interior).find("interior facet but has label 2"), std::string::npos);
    EXPECT_NE(
        message(labelled_interior).find("cube.flags: tetrahedron " + std::to_string(interior / 4)),
        std::string::npos);
    std::vector<int> unlabelled = flags;
    unlabelled[l.boundary.tet_facet[0]] = -1;
    EXPECT_NE(message(unlabelled).find("boundary facet without a label"), std::string::npos);
    std::vector<int> out_of_range = flags;
    out_of_range[l.boundary.tet_facet[3]] = 6;
    EXPECT_NE(message(out_of_range).find("outside [-1, 5]"), std::string::npos);
}

TEST(PolycubeLabeling, AChartWithoutASideCannotBePlanar) {
    const Labelled l = closest(voxel_tetrahedra({{0, 0, 0}}, 1));
    // Every boundary triangle labelled X: one chart around the whole cube, whose normals cancel.
    const std::vector<int> all_x(l.boundary.size(), 0);
    try {
        labels_from_file_axes(l.mesh, l.boundary, all_x, "cube.flags", nullptr);
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot be planar"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("cube.flags: the chart of 12"), std::string::npos);
    }
    EXPECT_THROW(validate_polycube_labels(l.mesh, l.boundary, all_x, "cube"), InputError);
    // One face labelled with the opposite direction faces away from it.
    std::vector<int> flipped = l.labels;
    for (Index b = 0; b < l.boundary.size(); ++b) {
        if (l.labels[b] == 0) flipped[b] = 1;
    }
    try {
        validate_polycube_labels(l.mesh, l.boundary, flipped, "cube");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("labelled -X"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("faces away"), std::string::npos) << e.what();
    }
}

TEST(PolycubeLabeling, OppositeChartsMustNotTouch) {
    const Labelled l = closest(roof());
    const PolycubeCharts charts = polycube_charts(l.boundary, l.mesh.vertices, l.labels);
    ASSERT_EQ(charts.size(), 5);
    try {
        validate_polycube_labels(l.mesh, l.boundary, l.labels, "roof");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("opposite sides of one axis"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace sa
