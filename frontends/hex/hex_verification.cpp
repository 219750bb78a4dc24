#include "frontends/hex/hex_verification.h"

#include <sstream>
#include <vector>

#include "geometry/quality/surface_distance.h"

namespace sa {

namespace {

/// The rows of `positions` that some row of `faces` refers to.
Eigen::MatrixXd referenced_rows(const Eigen::MatrixXd& positions, const Eigen::MatrixXi& faces) {
    std::vector<unsigned char> used(positions.rows(), 0);
    for (Eigen::Index i = 0; i < faces.size(); ++i) used[faces.data()[i]] = 1;
    std::vector<Eigen::Index> rows;
    for (Eigen::Index v = 0; v < positions.rows(); ++v)
        if (used[v]) rows.push_back(v);
    Eigen::MatrixXd out(static_cast<Eigen::Index>(rows.size()), positions.cols());
    for (std::size_t i = 0; i < rows.size(); ++i) out.row(Eigen::Index(i)) = positions.row(rows[i]);
    return out;
}

}  // namespace

HexVerification verify_hex_mesh(const HexMesh& hexes, const Eigen::MatrixXd& input_vertices,
                                const Eigen::MatrixXi& input_boundary, double input_volume) {
    HexVerification v;
    v.hexes = hexes.num_hexes();
    v.vertices = hexes.num_vertices();
    v.quality = hex_quality(hexes);
    const HexBoundary boundary = hex_boundary(hexes);
    v.boundary_faces = static_cast<Index>(boundary.quads.rows());
    v.open_boundary_edges = boundary.open_edges;
    v.faces_in_more_than_two_hexes = boundary.faces_in_more_than_two_hexes;
    v.diagonal = (input_vertices.colwise().maxCoeff() - input_vertices.colwise().minCoeff()).norm();
    if (v.hexes > 0 && input_boundary.rows() > 0 && v.diagonal > 0.0) {
        Eigen::MatrixXi triangles(2 * boundary.quads.rows(), 3);
        for (Eigen::Index q = 0; q < boundary.quads.rows(); ++q) {
            triangles.row(2 * q) << boundary.quads(q, 0), boundary.quads(q, 1),
                boundary.quads(q, 2);
            triangles.row(2 * q + 1) << boundary.quads(q, 0), boundary.quads(q, 2),
                boundary.quads(q, 3);
        }
        const SurfaceDistance input(input_vertices, input_boundary);
        v.distance_to_input =
            input.max_distance(referenced_rows(hexes.positions, boundary.quads)) / v.diagonal;
        if (triangles.rows() > 0) {
            const SurfaceDistance output(hexes.positions, triangles);
            v.distance_from_input =
                output.max_distance(referenced_rows(input_vertices, input_boundary)) / v.diagonal;
        }
    }
    v.volume_ratio = input_volume > 0.0 ? v.quality.volume / input_volume : 0.0;
    v.passed = v.hexes > 0 && v.quality.inverted == 0 && boundary.closed();
    std::ostringstream s;
    s << v.hexes << " hexes, " << v.quality.inverted << " inverted, boundary "
      << (boundary.closed() ? "closed"
                            : "NOT closed (" + std::to_string(v.open_boundary_edges) +
                                  " open or non-manifold edges)")
      << "; scaled Jacobian min " << v.quality.min_scaled_jacobian << ", mean "
      << v.quality.mean_scaled_jacobian << "; boundary distance " << v.distance_to_input << " / "
      << v.distance_from_input << " of the diagonal; volume ratio " << v.volume_ratio;
    v.summary = s.str();
    return v;
}

}  // namespace sa
