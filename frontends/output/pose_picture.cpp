#include "frontends/output/pose_picture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "frontends/output/surface_value_picture.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/rest_frames.h"
#include "geometry/quality/map_quality.h"
#include "optim/errors.h"

namespace sa {

namespace {

// Faces of tetrahedron s opposite each local vertex, oriented outwards for a positively
// oriented tetrahedron (the facet order of the data's README).
constexpr int kFacet[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

struct Faces {
    std::vector<Eigen::Vector3i> triangles;
    std::vector<Index> simplex;  // the simplex each triangle shows
};

void add_facet(Faces& faces, const SimplicialMesh& mesh, Index s, int opposite, bool flip) {
    Eigen::Vector3i t;
    for (int k = 0; k < 3; ++k) t[k] = mesh.simplices(s, kFacet[opposite][k]);
    if (flip) std::swap(t[1], t[2]);
    faces.triangles.push_back(t);
    faces.simplex.push_back(s);
}

}  // namespace

void write_pose_png(const std::string& path, const SimplicialMesh& rest,
                    const Eigen::MatrixXd& positions, const PosePicture& picture) {
    const int d = rest.simplex_dimension();
    if ((d != 2 && d != 3) || rest.ambient_dimension() != d) {
        throw InvalidArgumentError(
            "write_pose_png: expected planar triangles or tetrahedra, got simplices of "
            "dimension " +
            std::to_string(d) + " in " + std::to_string(rest.ambient_dimension()) + "D");
    }
    if (positions.rows() != rest.num_vertices() || positions.cols() != d) {
        throw InvalidArgumentError("write_pose_png: positions are " +
                                   std::to_string(positions.rows()) + " x " +
                                   std::to_string(positions.cols()) + ", expected " +
                                   std::to_string(rest.num_vertices()) + " x " + std::to_string(d));
    }
    MapQuality quality;
    std::vector<double> rest_orientation;  // tetrahedra: the sign of each rest volume
    if (d == 2) {
        const RestFrames<2> frames = rest_frames<2>(rest);
        quality = map_quality<2>(linear_parts<2>(rest, frames, positions), frames.volume);
    } else {
        const RestFrames<3> frames = rest_frames<3>(rest);
        quality = map_quality<3>(linear_parts<3>(rest, frames, positions), frames.volume);
        // Tetrahedra keep the mesh's axes in their frames: the sign of the rest volume.
        for (Index s = 0; s < rest.num_simplices(); ++s)
            rest_orientation.push_back(frames.edge_inverse[s].determinant());
    }

    // Red: the inverted simplices and the marked ones.
    std::vector<unsigned char> red(rest.num_simplices(), 0);
    for (Index s = 0; s < rest.num_simplices(); ++s) red[s] = quality.per_simplex[s].inverted;
    Index marked = 0;
    for (Index s : picture.marked) {
        if (s < 0 || s >= rest.num_simplices()) {
            throw InvalidArgumentError("write_pose_png: marked simplex " + std::to_string(s) +
                                       " outside [0, " + std::to_string(rest.num_simplices()) +
                                       ")");
        }
        marked += !red[s];
        red[s] = 1;
    }

    // The faces to draw: every triangle (2D); the boundary facets and every facet of the red
    // tetrahedra (3D: a folded one is often behind the surface, even one with a boundary facet).
    Faces faces;
    if (d == 2) {
        for (Index s = 0; s < rest.num_simplices(); ++s) {
            faces.triangles.emplace_back(rest.simplices(s, 0), rest.simplices(s, 1),
                                         rest.simplices(s, 2));
            faces.simplex.push_back(s);
        }
    } else {
        const MeshTopology topology = mesh_topology(rest, "write_pose_png");
        for (const BoundaryFacet& f : topology.boundary_facets)
            add_facet(faces, rest, f.simplex, f.opposite, rest_orientation[f.simplex] < 0.0);
        for (Index s = 0; s < rest.num_simplices(); ++s) {
            if (!red[s]) continue;
            for (int k = 0; k < 4; ++k) add_facet(faces, rest, s, k, false);
        }
    }

    const Eigen::Index n = static_cast<Eigen::Index>(faces.triangles.size());
    Eigen::MatrixXi triangles(n, 3);
    Eigen::VectorXd values(n);
    std::vector<unsigned char> flagged(n, 0);
    std::vector<double> finite;
    for (Eigen::Index f = 0; f < n; ++f) {
        triangles.row(f) = faces.triangles[f].transpose();
        const SimplexQuality& q = quality.per_simplex[faces.simplex[f]];
        values[f] = q.isometric;
        flagged[f] = red[faces.simplex[f]];
        if (std::isfinite(q.isometric)) finite.push_back(q.isometric);
    }
    // The default range ends at the 99th percentile of the faces' values: a few extreme
    // simplices (next to inverted ones) would otherwise leave the rest in the first colour.
    double high = picture.low + 0.5;
    if (!finite.empty()) {
        const std::size_t k = (finite.size() - 1) * 99 / 100;
        std::nth_element(finite.begin(), finite.begin() + k, finite.end());
        high = std::max(high, finite[k]);
    }
    Eigen::MatrixXd points = Eigen::MatrixXd::Zero(positions.rows(), 3);
    points.leftCols(d) = positions;

    SurfaceValuePicture view;
    view.value_name = "isometric distortion";
    view.width = picture.width;
    view.height = picture.height;
    view.azimuth = d == 2 ? 0.0 : picture.azimuth;
    view.elevation = d == 2 ? 0.0 : picture.elevation;
    view.low = picture.low;
    view.high = picture.high > picture.low ? picture.high : high;
    const bool see_through = d == 3 && (quality.inverted > 0 || marked > 0);
    view.opacity = see_through ? picture.see_through_opacity : 1.0;
    view.title = picture.title;
    if (view.title.empty()) {
        char text[256];
        std::snprintf(text, sizeof text, "%ld inverted%s of %ld %s; isometric max %.3g mean %.3g",
                      long(quality.inverted),
                      quality.inverted == 0 ? ""
                      : see_through         ? " (red, seen through the surface)"
                                            : " (red)",
                      long(quality.simplices), d == 2 ? "triangles" : "tetrahedra",
                      quality.isometric.max, quality.isometric.mean);
        view.title = text;
        if (marked > 0)
            view.title += "; " + std::to_string(marked) + " " + picture.marked_label + " in red";
    }
    write_surface_value_png(path, points, triangles, values, view, flagged);
}

}  // namespace sa
