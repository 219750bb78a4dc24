#include "frontends/polycube/boundary_angle_sums.h"

#include "frontends/polycube/tet_angle_barriers.h"

namespace sa {

namespace {

Eigen::Vector3d at(const Eigen::MatrixXd& positions, Index v) {
    return positions.row(v).transpose();
}

}  // namespace

std::vector<double> dihedral_angle_sums(const std::vector<BoundaryEdgeFan>& fans,
                                        const Eigen::MatrixXd& positions) {
    std::vector<double> sums(fans.size(), 0.0);
    for (std::size_t f = 0; f < fans.size(); ++f) {
        const Eigen::Vector3d p = at(positions, fans[f].edge[0]);
        const Eigen::Vector3d e = at(positions, fans[f].edge[1]) - p;
        for (const auto& rs : fans[f].others) {
            bool defined = true;
            const double angle = dihedral_angle<double>(e, at(positions, rs[0]) - p,
                                                        at(positions, rs[1]) - p, &defined);
            sums[f] += defined ? angle : kInfinity;
        }
    }
    return sums;
}

std::vector<double> solid_angle_sums(const std::vector<BoundaryVertexStar>& stars,
                                     const Eigen::MatrixXd& positions) {
    std::vector<double> sums(stars.size(), 0.0);
    for (std::size_t s = 0; s < stars.size(); ++s) {
        const Eigen::Vector3d v = at(positions, stars[s].vertex);
        for (const auto& abc : stars[s].others) {
            bool defined = true;
            const double angle =
                solid_angle<double>(at(positions, abc[0]) - v, at(positions, abc[1]) - v,
                                    at(positions, abc[2]) - v, &defined);
            sums[s] += defined ? angle : kInfinity;
        }
    }
    return sums;
}

}  // namespace sa
