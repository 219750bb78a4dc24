#include "frontends/hex/hex_padding.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/quality/hex_quality.h"
#include "optim/errors.h"

namespace sa {

HexPadding pad_boundary(const HexMesh& mesh, double depth) {
    if (!(depth > 0.0) || !std::isfinite(depth))
        throw InvalidArgumentError("pad_boundary: the depth must be finite and > 0");
    const HexBoundary boundary = hex_boundary(mesh);
    const Index nv = mesh.num_vertices(), nh = mesh.num_hexes();
    const Eigen::Index nq = boundary.quads.rows();
    std::vector<Index> copy(nv, -1);
    Index next = nv;
    for (Eigen::Index i = 0; i < boundary.quads.size(); ++i) {
        Index& c = copy[boundary.quads.data()[i]];
        if (c < 0) c = next++;
    }
    HexPadding out;
    out.added_hexes = static_cast<Index>(nq);
    out.mesh.positions.resize(next, 3);
    out.mesh.positions.topRows(nv) = mesh.positions;
    out.source.resize(next);
    for (Index v = 0; v < nv; ++v) {
        out.source[v] = v;
        if (copy[v] < 0) continue;
        out.mesh.positions.row(copy[v]) = mesh.positions.row(v);
        out.source[copy[v]] = v;
    }
    out.mesh.hexes.resize(nh + nq, 8);
    out.mesh.hexes.topRows(nh) = mesh.hexes;
    // The outward quad (a, b, c, d) turns counter-clockwise seen from outside: the bottom of a
    // hex whose top (the copies) is outside.
    for (Eigen::Index q = 0; q < nq; ++q) {
        for (int k = 0; k < 4; ++k) {
            out.mesh.hexes(nh + q, k) = boundary.quads(q, k);
            out.mesh.hexes(nh + q, k + 4) = copy[boundary.quads(q, k)];
        }
    }
    // The old boundary vertices move inward along the mean of their quads' normals m, by
    // depth / min_q (m . n_q): each adjacent quad's plane then moves by at least the depth, as a
    // box's corner moves along its diagonal by sqrt(3) times it. The factor is at most 2.
    std::vector<Eigen::Vector3d> unit_normal(static_cast<std::size_t>(nq));
    Eigen::MatrixXd mean = Eigen::MatrixXd::Zero(nv, 3);
    std::vector<double> length(nv, 0.0);
    std::vector<int> edges(nv, 0);
    for (Eigen::Index q = 0; q < nq; ++q) {
        Eigen::Vector3d x[4];
        for (int k = 0; k < 4; ++k) x[k] = mesh.positions.row(boundary.quads(q, k)).transpose();
        const Eigen::Vector3d area = 0.5 * (x[2] - x[0]).cross(x[3] - x[1]);  // outward
        const double norm = area.norm();
        unit_normal[q] = norm > 0.0 ? Eigen::Vector3d(area / norm) : Eigen::Vector3d::Zero();
        for (int k = 0; k < 4; ++k) {
            const Index v = boundary.quads(q, k);
            mean.row(v) += area.transpose();
            length[v] += (x[(k + 1) % 4] - x[k]).norm() + (x[(k + 3) % 4] - x[k]).norm();
            edges[v] += 2;
        }
    }
    std::vector<double> least_cosine(nv, 1.0);
    for (Eigen::Index q = 0; q < nq; ++q) {
        for (int k = 0; k < 4; ++k) {
            const Index v = boundary.quads(q, k);
            const double m = mean.row(v).norm();
            if (m > 0.0)
                least_cosine[v] =
                    std::min(least_cosine[v], mean.row(v).dot(unit_normal[q].transpose()) / m);
        }
    }
    for (Index v = 0; v < nv; ++v) {
        const double m = mean.row(v).norm();
        if (copy[v] < 0 || !(m > 0.0)) continue;
        const double stretch = 1.0 / std::max(least_cosine[v], 0.5);
        out.mesh.positions.row(v) -= depth * stretch * (length[v] / edges[v]) * mean.row(v) / m;
    }
    return out;
}

}  // namespace sa
