#include "geometry/mesh/simplicial_mesh.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <sstream>

#include "optim/errors.h"

namespace sa {

double bounding_box_diagonal(const Eigen::MatrixXd& points) {
    if (points.rows() == 0) return 0.0;
    const Eigen::RowVectorXd extent = points.colwise().maxCoeff() - points.colwise().minCoeff();
    const double diagonal = extent.norm();
    // The squares under norm() overflow beyond 1e154 and underflow below 1e-154: scale first
    // there (stableNorm), and only there, so that other meshes get the same bits as before.
    if ((diagonal == 0.0 || !std::isfinite(diagonal)) && extent.allFinite())
        return extent.stableNorm();
    return diagonal;
}

int scale_exponent(const Eigen::MatrixXd& points) {
    const double diagonal = bounding_box_diagonal(points);
    return diagonal > 0.0 && std::isfinite(diagonal) ? std::ilogb(diagonal) : 0;
}

void validate_mesh(const SimplicialMesh& mesh, const std::string& source) {
    auto fail = [&](const std::string& what) { throw InputError(source + ": " + what); };
    const int dim = mesh.ambient_dimension();
    const int k = static_cast<int>(mesh.simplices.cols());
    if (mesh.num_vertices() == 0) fail("no vertices");
    if (mesh.num_simplices() == 0) fail("no triangles or tetrahedra");
    if (dim != 2 && dim != 3)
        fail("vertices have " + std::to_string(dim) + " coordinates, expected 2 or 3");
    if (k != 3 && k != 4)
        fail("simplices have " + std::to_string(k) + " vertices, expected 3 or 4");
    if (k == 4 && dim != 3) fail("tetrahedra need 3D vertex positions");
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        if (!mesh.vertices.row(v).allFinite())
            fail("vertex " + std::to_string(v) + " has a non-finite coordinate");
    }
    const double diagonal = bounding_box_diagonal(mesh.vertices);
    if (!std::isfinite(diagonal))
        fail("the vertices span more than the range of a double (bounding-box diagonal " +
             std::to_string(diagonal) + ")");
    // A simplex is degenerate when its volume is below this fraction of diagonal^d. Measured on
    // edges divided by the diagonal, so that a mesh at any scale in the range of a double gives
    // the same answer (at 1e200 the cross product overflowed, at 1e-200 it underflowed).
    const double tiny = 1e-14;
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        for (int a = 0; a < k; ++a) {
            const int v = mesh.simplices(s, a);
            if (v < 0 || v >= mesh.num_vertices()) {
                std::ostringstream msg;
                msg << "simplex " << s << " names vertex " << v << ", outside [0, "
                    << mesh.num_vertices() << ")";
                fail(msg.str());
            }
            for (int b = 0; b < a; ++b) {
                if (mesh.simplices(s, b) == v) {
                    fail("simplex " + std::to_string(s) + " uses vertex " + std::to_string(v) +
                         " twice");
                }
            }
        }
        double volume;
        if (k == 4) {
            Eigen::Matrix3d e;
            for (int c = 0; c < 3; ++c)
                e.col(c) = (mesh.vertices.row(mesh.simplices(s, c + 1)) -
                            mesh.vertices.row(mesh.simplices(s, 0)))
                               .transpose() /
                           diagonal;
            volume = std::abs(e.determinant()) / 6.0;
        } else {
            Eigen::Vector3d p[3];
            for (int c = 0; c < 3; ++c) {
                p[c].setZero();
                p[c].head(dim) = mesh.vertices.row(mesh.simplices(s, c)).transpose() / diagonal;
            }
            volume = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
        }
        if (!(volume > tiny)) {
            std::ostringstream msg;
            msg << "simplex " << s << " is degenerate in the rest shape (volume " << volume
                << " times the bounding-box diagonal to the power " << k - 1 << ", below " << tiny
                << ")";
            fail(msg.str());
        }
    }
}

}  // namespace sa
