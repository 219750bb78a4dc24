#include "frontends/polycube/polycube_output.h"

#include <algorithm>

#include "frontends/output/map_output.h"
#include "frontends/output/surface_value_picture.h"
#include "geometry/io/medit_io.h"
#include "geometry/io/polycube_labels_io.h"
#include "geometry/io/vtk_io.h"
#include "optim/errors.h"

namespace sa {

namespace {

std::string without_mesh_extension(const std::string& out) {
    const std::string ext = ".mesh";
    if (out.size() > ext.size() &&
        std::equal(ext.rbegin(), ext.rend(), out.rbegin(), [](char a, char b) {
            return a == std::tolower(static_cast<unsigned char>(b));
        })) {
        return out.substr(0, out.size() - ext.size());
    }
    throw InvalidArgumentError(out + ": the PolyCube map is written as a .mesh file");
}

void check_positions(const PreparedPolycube& prepared, const Eigen::MatrixXd& positions,
                     const char* who) {
    if (positions.rows() != prepared.mesh.num_vertices() || positions.cols() != 3) {
        throw InvalidArgumentError(std::string(who) + ": positions must be #V x 3 = " +
                                   std::to_string(prepared.mesh.num_vertices()) + " x 3");
    }
}

}  // namespace

std::string polycube_rest_path(const std::string& out) {
    return without_mesh_extension(out) + ".rest.mesh";
}

std::string polycube_flags_path(const std::string& out) {
    return without_mesh_extension(out) + ".flags";
}

void write_polycube_map(const std::string& out, const PreparedPolycube& prepared,
                        const Eigen::MatrixXd& positions) {
    check_positions(prepared, positions, "write_polycube_map");
    write_medit(out, prepared.in_input_units(positions), prepared.mesh.simplices);
}

void write_polycube_meshes(const std::string& out, const PreparedPolycube& prepared,
                           const Eigen::MatrixXd& positions) {
    check_positions(prepared, positions, "write_polycube_meshes");  // before any file is written
    const std::string rest = polycube_rest_path(out), flags = polycube_flags_path(out);
    write_medit(rest, prepared.rest_positions(), prepared.mesh.simplices);
    write_facet_flags(flags, prepared.output_flags());
    write_polycube_map(out, prepared, positions);
}

void write_polycube_vtu(const std::string& path, const PreparedPolycube& prepared,
                        const Eigen::MatrixXd& positions,
                        const PolycubeVerification& verification) {
    check_positions(prepared, positions, "write_polycube_vtu");
    std::vector<DataArray> cells = quality_cell_data(verification.quality);
    const std::vector<int> flags = prepared.output_flags();
    DataArray labels{"facet_labels", Eigen::MatrixXd(prepared.mesh.num_simplices(), 4), true};
    for (Index t = 0; t < prepared.mesh.num_simplices(); ++t) {
        for (int k = 0; k < 4; ++k) labels.values(t, k) = flags[4 * t + k];
    }
    cells.push_back(std::move(labels));
    DataArray rest{"rest", prepared.rest_positions(), false};
    const Eigen::MatrixXd mapped = prepared.in_input_units(positions);
    if (path.size() >= 4 && path.substr(path.size() - 4) == ".vtk") {
        write_vtk(path, mapped, prepared.mesh.simplices, {rest}, cells);
    } else {
        write_vtu(path, mapped, prepared.mesh.simplices, {rest}, cells);
    }
}

void write_polycube_png(const std::string& path, const PreparedPolycube& prepared,
                        const Eigen::MatrixXd& positions, const PolycubeVerification& verification,
                        const std::string& title) {
    check_positions(prepared, positions, "write_polycube_png");
    const TetBoundary& boundary = prepared.boundary;
    Eigen::VectorXd values(boundary.size());
    std::vector<unsigned char> inverted(boundary.size(), 0);
    std::vector<double> finite;
    for (Index b = 0; b < boundary.size(); ++b) {
        const SimplexQuality& q = verification.quality.per_simplex[boundary.tet(b)];
        inverted[b] = q.inverted || q.degenerate;
        values[b] = q.conformal;
        if (!inverted[b] && std::isfinite(q.conformal)) finite.push_back(q.conformal);
    }
    // The colours span [1, the 99th percentile] (at least [1, 2]), so that a few extreme
    // tetrahedra do not darken the rest; higher values take the last colour.
    double high = 2.0;
    if (!finite.empty()) {
        const auto at = finite.begin() + std::ptrdiff_t(0.99 * double(finite.size() - 1));
        std::nth_element(finite.begin(), at, finite.end());
        high = std::max(high, *at);
    }
    SurfaceValuePicture picture;
    picture.title = title;
    picture.value_name = "conformal distortion";
    picture.low = 1.0;
    picture.high = high;
    write_surface_value_png(path, positions, boundary.triangles, values, picture, inverted);
}

}  // namespace sa
