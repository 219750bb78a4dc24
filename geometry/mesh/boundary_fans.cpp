#include "geometry/mesh/boundary_fans.h"

#include <cmath>

#include "geometry/mesh/boundary_loops.h"
#include "geometry/mesh/rest_frames.h"
#include "optim/errors.h"

namespace sa {

std::vector<BoundaryFan> boundary_fans(const SimplicialMesh& mesh, const MeshTopology& topology) {
    // The triangle around v in which v is directly followed by u, and the corner after u.
    auto following = [&](Index v, Index u, Index* third) -> Index {
        for (Index i = topology.vertex_begin[v]; i < topology.vertex_begin[v + 1]; ++i) {
            const Index t = topology.simplices_of_vertex[i];
            for (int k = 0; k < 3; ++k) {
                if (mesh.simplices(t, k) == v && mesh.simplices(t, (k + 1) % 3) == u) {
                    *third = mesh.simplices(t, (k + 2) % 3);
                    return t;
                }
            }
        }
        return -1;
    };
    std::vector<BoundaryFan> fans;
    for (const std::vector<Index>& loop : boundary_loops(mesh, topology)) {
        for (std::size_t k = 0; k < loop.size(); ++k) {
            BoundaryFan fan;
            fan.vertex = loop[k];
            const Index next = loop[(k + 1) % loop.size()],
                        previous = loop[(k + loop.size() - 1) % loop.size()];
            fan.neighbours.push_back(next);
            Index u = next;
            while (u != previous) {
                Index third = -1;
                const Index t = following(fan.vertex, u, &third);
                if (t < 0 || fan.triangles.size() > topology.simplices_of_vertex.size()) {
                    throw InputError(
                        "boundary vertex " + std::to_string(fan.vertex) +
                        ": its triangles do not form a fan (inconsistent orientation?)");
                }
                fan.triangles.push_back(t);
                fan.neighbours.push_back(third);
                u = third;
            }
            fans.push_back(std::move(fan));
        }
    }
    return fans;
}

Mat<2> fan_edges(const SimplicialMesh& mesh, const RestFrames<2>& frames, const BoundaryFan& fan,
                 std::size_t k) {
    const Index t = fan.triangles[k];
    auto corner = [&](Index v) -> Vec<2> {
        for (int c = 0; c < 3; ++c) {
            if (mesh.simplices(t, c) == v) return frames.corner(t, c);
        }
        throw InvalidArgumentError("fan_edges: vertex " + std::to_string(v) +
                                   " is not in triangle " + std::to_string(t));
    };
    const Vec<2> u = corner(fan.vertex);
    Mat<2> E;
    E << corner(fan.neighbours[k]) - u, corner(fan.neighbours[k + 1]) - u;
    return E;
}

std::vector<double> boundary_angle_sums(const std::vector<BoundaryFan>& fans,
                                        const Eigen::MatrixXd& uv) {
    std::vector<double> sums;
    sums.reserve(fans.size());
    for (const BoundaryFan& fan : fans) {
        double theta = 0.0;
        const Eigen::Vector2d p = uv.row(fan.vertex).head<2>();
        for (std::size_t k = 0; k < fan.triangles.size(); ++k) {
            const Eigen::Vector2d a = uv.row(fan.neighbours[k]).head<2>().transpose() - p;
            const Eigen::Vector2d b = uv.row(fan.neighbours[k + 1]).head<2>().transpose() - p;
            theta += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
        }
        sums.push_back(theta);
    }
    return sums;
}

Index count_boundary_violations(const std::vector<BoundaryFan>& fans, const Eigen::MatrixXd& uv) {
    Index count = 0;
    for (double theta : boundary_angle_sums(fans, uv)) count += !(theta < 2.0 * M_PI);
    return count;
}

}  // namespace sa
