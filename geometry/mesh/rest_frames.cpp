#include "geometry/mesh/rest_frames.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "optim/errors.h"

namespace sa {

template <int D>
RestFrames<D> rest_frames(const SimplicialMesh& mesh) {
    if (mesh.simplex_dimension() != D) {
        throw InvalidArgumentError("rest_frames<" + std::to_string(D) +
                                   ">: the mesh has simplices of dimension " +
                                   std::to_string(mesh.simplex_dimension()));
    }
    const Index n = mesh.num_simplices();
    RestFrames<D> frames;
    frames.corners.resize(n);
    frames.edge_inverse.resize(n);
    frames.volume.resize(n);
    const bool surface = D == 2 && mesh.ambient_dimension() == 3;
    if (surface) frames.axes.resize(n);
    for (Index s = 0; s < n; ++s) {
        Eigen::Matrix<double, D, D + 1> c;
        if constexpr (D == 2) {
            if (surface) {
                Eigen::Vector3d p[3];
                for (int k = 0; k < 3; ++k)
                    p[k] = mesh.vertices.row(mesh.simplices(s, k)).transpose();
                const Eigen::Vector3d centroid = (p[0] + p[1] + p[2]) / 3.0;
                const Eigen::Vector3d x = (p[1] - p[0]).normalized();
                const Eigen::Vector3d normal = (p[1] - p[0]).cross(p[2] - p[0]);
                const Eigen::Vector3d y = normal.cross(x).normalized();
                frames.axes[s] << x, y;
                for (int k = 0; k < 3; ++k)
                    c.col(k) = frames.axes[s].transpose() * (p[k] - centroid);
            }
        }
        if (!surface) {
            for (int k = 0; k <= D; ++k) {
                c.col(k) = mesh.vertices.row(mesh.simplices(s, k)).transpose().template head<D>();
            }
            c.colwise() -= c.rowwise().mean();
        }
        Mat<D> edges;
        for (int k = 0; k < D; ++k) edges.col(k) = c.col(k + 1) - c.col(0);
        frames.corners[s] = c;
        frames.edge_inverse[s] = edges.inverse();
        frames.volume[s] = std::abs(edges.determinant()) / (D == 2 ? 2.0 : 6.0);
    }
    return frames;
}

template RestFrames<2> rest_frames<2>(const SimplicialMesh&);
template RestFrames<3> rest_frames<3>(const SimplicialMesh&);

}  // namespace sa
