#include "frontends/seamless/frame_field.h"

#include <Eigen/SVD>
#include <cmath>

#include "optim/errors.h"

namespace sa {

namespace {

int local_index(const SimplicialMesh& mesh, Index f, Index v) {
    for (int k = 0; k < 3; ++k) {
        if (mesh.simplices(f, k) == v) return k;
    }
    throw InvalidArgumentError("frame field: vertex " + std::to_string(v) + " is not in face " +
                               std::to_string(f));
}

}  // namespace

std::vector<Mat<2>> frame_matrices(const RestFrames<2>& frames, const Eigen::MatrixXd& u,
                                   const Eigen::MatrixXd& v) {
    const Index nf = frames.size();
    const bool cross = v.rows() == 0;
    if (u.rows() != nf || u.cols() != 3 || (!cross && (v.rows() != nf || v.cols() != 3))) {
        throw InvalidArgumentError("frame field: expected #F x 3 vectors for " +
                                   std::to_string(nf) + " faces");
    }
    if (Index(frames.axes.size()) != nf)
        throw InvalidArgumentError("frame field: needs a triangle mesh in space (3 coordinates)");
    std::vector<Mat<2>> matrices(nf);
    for (Index f = 0; f < nf; ++f) {
        const Eigen::Matrix<double, 3, 2>& axes = frames.axes[f];
        const Vec<2> a = axes.transpose() * u.row(f).transpose();
        if (!(a.norm() > 1e-6 * u.row(f).norm()) || !a.allFinite()) {
            throw InputError("frame field: the first vector of face " + std::to_string(f) +
                             " is zero or normal to the face");
        }
        Vec<2> b = cross ? Vec<2>(-a.y(), a.x()) : Vec<2>(axes.transpose() * v.row(f).transpose());
        const double det = a.x() * b.y() - a.y() * b.x();
        if (!(std::abs(det) > 1e-6 * a.norm() * b.norm())) {
            throw InputError("frame field: the two vectors of face " + std::to_string(f) +
                             " are parallel (or the second vanishes) in the face's plane");
        }
        if (det < 0.0) b = -b;
        matrices[f].row(0) = a.transpose();
        matrices[f].row(1) = b.transpose();
    }
    return matrices;
}

std::pair<Eigen::MatrixXd, Eigen::MatrixXd> frame_vectors(const RestFrames<2>& frames,
                                                          const std::vector<Mat<2>>& matrices) {
    Eigen::MatrixXd u(frames.size(), 3), v(frames.size(), 3);
    for (Index f = 0; f < frames.size(); ++f) {
        u.row(f) = (frames.axes[f] * matrices[f].row(0).transpose()).transpose();
        v.row(f) = (frames.axes[f] * matrices[f].row(1).transpose()).transpose();
    }
    return {u, v};
}

Eigen::MatrixXd frame_cross_directions(const RestFrames<2>& frames,
                                       const std::vector<Mat<2>>& matrices) {
    Eigen::MatrixXd directions(frames.size(), 3);
    for (Index f = 0; f < frames.size(); ++f) {
        const Eigen::JacobiSVD<Mat<2>> svd(matrices[f], Eigen::ComputeFullU | Eigen::ComputeFullV);
        Mat<2> V = svd.matrixV();
        if ((svd.matrixU() * V.transpose()).determinant() < 0.0) V.col(1) = -V.col(1);
        const Mat<2> rotation = svd.matrixU() * V.transpose();
        directions.row(f) = (frames.axes[f] * rotation.row(0).transpose()).transpose();
    }
    return directions;
}

double mean_row_norm(const std::vector<Mat<2>>& matrices) {
    double sum = 0.0;
    for (const Mat<2>& A : matrices) sum += A.row(0).norm() + A.row(1).norm();
    return sum / (2.0 * double(matrices.size()));
}

Mat<2> quarter_turns(int k) {
    const int m = ((k % 4) + 4) % 4;
    const double c = m == 0 ? 1.0 : m == 2 ? -1.0 : 0.0, s = m == 1 ? 1.0 : m == 3 ? -1.0 : 0.0;
    Mat<2> r;
    r << c, -s, s, c;
    return r;
}

std::pair<Vec<2>, Vec<2>> facet_edge_in_frames(const SimplicialMesh& mesh,
                                               const RestFrames<2>& frames,
                                               const InteriorFacet& facet) {
    auto edge = [&](Index f) {
        const Vec<2> e = frames.corner(f, local_index(mesh, f, facet.vertices[1])) -
                         frames.corner(f, local_index(mesh, f, facet.vertices[0]));
        return Vec<2>(e / e.norm());
    };
    return {edge(facet.simplex[0]), edge(facet.simplex[1])};
}

Eigen::VectorXd edge_curl(const SimplicialMesh& mesh, const MeshTopology& topology,
                          const RestFrames<2>& frames, const std::vector<Mat<2>>& matrices,
                          const std::vector<int>& matching) {
    const std::size_t ne = topology.interior_facets.size();
    if (matching.size() != ne || Index(matrices.size()) != mesh.num_simplices()) {
        throw InvalidArgumentError(
            "edge_curl: expected one matrix per face and one matching per interior edge");
    }
    Eigen::VectorXd curl(ne);
    for (std::size_t i = 0; i < ne; ++i) {
        const InteriorFacet& facet = topology.interior_facets[i];
        const auto [ef, eg] = facet_edge_in_frames(mesh, frames, facet);
        curl[i] = (matrices[facet.simplex[0]] * ef -
                   quarter_turns(matching[i]) * matrices[facet.simplex[1]] * eg)
                      .norm();
    }
    return curl;
}

}  // namespace sa
