#include "geometry/quality/branch_points.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <complex>
#include <queue>

#include "geometry/mesh/submesh.h"
#include "optim/errors.h"

namespace sa {

namespace {

using Complex = std::complex<double>;

Complex at(const Eigen::MatrixXd& positions, Index v) {
    return {positions(v, 0), positions(v, 1)};
}

/// The angle from a to b in (-pi, pi].
double turn(Complex a, Complex b) {
    return std::arg(b / a);
}

Complex centroid(const SimplicialMesh& mesh, const Eigen::MatrixXd& positions, Index s) {
    return (at(positions, mesh.simplices(s, 0)) + at(positions, mesh.simplices(s, 1)) +
            at(positions, mesh.simplices(s, 2))) /
           3.0;
}

}  // namespace

double turning_number(const std::vector<Index>& loop, const Eigen::MatrixXd& positions) {
    std::vector<Complex> points;
    for (Index v : loop) {
        const Complex p = at(positions, v);
        if (points.empty() || p != points.back()) points.push_back(p);
    }
    while (points.size() > 1 && points.front() == points.back()) points.pop_back();
    const std::size_t n = points.size();
    if (n < 3) return 0.0;
    double total = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        total += turn(points[(k + 1) % n] - points[k], points[(k + 2) % n] - points[(k + 1) % n]);
    }
    return total / (2.0 * M_PI);
}

double winding_number(const std::vector<Index>& loop, const Eigen::MatrixXd& positions,
                      const Eigen::Vector2d& point) {
    const Complex w(point.x(), point.y());
    double total = 0.0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
        const Complex a = at(positions, loop[k]) - w,
                      b = at(positions, loop[(k + 1) % loop.size()]) - w;
        if (a != 0.0 && b != 0.0) total += turn(a, b);
    }
    return total / (2.0 * M_PI);
}

std::vector<std::vector<Index>> region_boundary_loops(const SimplicialMesh& mesh,
                                                      const std::vector<Index>& region) {
    std::vector<std::pair<Index, Index>> edges;  // directed, as the triangles list them
    for (Index s : region) {
        for (int k = 0; k < 3; ++k)
            edges.emplace_back(mesh.simplices(s, k), mesh.simplices(s, (k + 1) % 3));
    }
    std::sort(edges.begin(), edges.end());
    std::vector<std::pair<Index, Index>> boundary;  // (from, to), sorted by from
    for (const auto& [a, b] : edges) {
        if (!std::binary_search(edges.begin(), edges.end(), std::pair{b, a}))
            boundary.emplace_back(a, b);
    }
    for (std::size_t k = 1; k < boundary.size(); ++k) {
        if (boundary[k].first == boundary[k - 1].first) return {};  // pinched
    }
    auto next = [&](Index v) {
        const auto it = std::lower_bound(boundary.begin(), boundary.end(), std::pair{v, Index(-1)});
        return it != boundary.end() && it->first == v ? it - boundary.begin() : -1;
    };
    std::vector<unsigned char> used(boundary.size(), 0);
    std::vector<std::vector<Index>> loops;
    for (std::size_t start = 0; start < boundary.size(); ++start) {
        if (used[start]) continue;
        std::vector<Index> loop;
        for (std::ptrdiff_t e = start; e >= 0 && !used[e]; e = next(boundary[e].second)) {
            used[e] = 1;
            loop.push_back(boundary[e].first);
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

namespace {

/// The regions of `rings` rings around `bad` with a single boundary loop, and its turning number.
std::vector<std::pair<std::vector<Index>, std::vector<Index>>> fold_regions(
    const SimplicialMesh& mesh, const MeshTopology& topology, const std::vector<Index>& bad,
    int rings) {
    std::vector<std::pair<std::vector<Index>, std::vector<Index>>> result;  // (region, loop)
    for (std::vector<Index>& region : vertex_connected_regions(
             mesh, topology, fill_enclosed(topology, grow_rings(mesh, topology, bad, rings)))) {
        std::vector<std::vector<Index>> loops = region_boundary_loops(mesh, region);
        if (loops.size() == 1) result.emplace_back(std::move(region), std::move(loops.front()));
    }
    return result;
}

}  // namespace

Index count_unrepairable_folds(const SimplicialMesh& mesh, const MeshTopology& topology,
                               const Eigen::MatrixXd& positions, const std::vector<Index>& bad,
                               int rings) {
    Index count = 0;
    for (const auto& [region, loop] : fold_regions(mesh, topology, bad, rings)) {
        const double turning = turning_number(loop, positions);
        count += std::abs(turning - 1.0) > 0.5;
    }
    return count;
}

std::vector<BranchPoint> find_branch_points(const SimplicialMesh& mesh,
                                            const MeshTopology& topology,
                                            const Eigen::MatrixXd& positions,
                                            const std::vector<Index>& bad, int rings) {
    if (mesh.simplex_dimension() != 2 || positions.cols() < 2 ||
        positions.rows() != mesh.num_vertices()) {
        throw InvalidArgumentError("find_branch_points: a triangle mesh and #V x 2 positions");
    }
    std::vector<BranchPoint> points;
    for (const auto& [region, loop] : fold_regions(mesh, topology, bad, rings)) {
        const double turning = turning_number(loop, positions);
        const long tau = std::lround(turning);
        if (tau < 2 || std::abs(turning - double(tau)) > 0.25) continue;
        BranchPoint point;
        point.turning = static_cast<int>(tau);
        for (Index s : bad) {
            if (std::binary_search(region.begin(), region.end(), s)) point.simplices.push_back(s);
        }
        // The fold's image w_k = f(z_k), z_k the critical point, where the map's scale vanishes:
        // of the triangles near the fold whose centroid the most loops around it (one per ring,
        // and the region's) wind around tau times, the one whose image is smallest relative to
        // its rest area.
        std::vector<std::vector<Index>> around{loop};
        for (int r = 1; r < rings; ++r) {
            const auto ring_loops =
                region_boundary_loops(mesh, grow_rings(mesh, topology, point.simplices, r));
            if (ring_loops.size() == 1) around.push_back(ring_loops.front());
        }
        int best = 0;
        double smallest = kInfinity;
        for (Index s : grow_rings(mesh, topology, point.simplices, 2)) {
            const Complex c = centroid(mesh, positions, s);
            const Eigen::Vector2d candidate(c.real(), c.imag());
            int wound = 0;
            for (const auto& l : around)
                wound += std::abs(winding_number(l, positions, candidate) - double(tau)) < 0.25;
            const Complex e1 = at(positions, mesh.simplices(s, 1)) -
                               at(positions, mesh.simplices(s, 0)),
                          e2 = at(positions, mesh.simplices(s, 2)) -
                               at(positions, mesh.simplices(s, 0));
            const Eigen::Vector3d p0 = mesh.point(mesh.simplices(s, 0));
            const double rest = (mesh.point(mesh.simplices(s, 1)) - p0)
                                    .cross(mesh.point(mesh.simplices(s, 2)) - p0)
                                    .norm();
            const double scale = std::abs(std::imag(std::conj(e1) * e2)) / rest;
            if (wound > best || (wound == best && wound > 0 && scale < smallest)) {
                best = wound;
                smallest = scale;
                point.image = candidate;
            }
        }
        if (best > 0) points.push_back(std::move(point));
    }
    return points;
}

Eigen::MatrixXd remove_branch_points(const SimplicialMesh& mesh, const MeshTopology& topology,
                                     const Eigen::MatrixXd& positions,
                                     const std::vector<BranchPoint>& points) {
    if (mesh.simplex_dimension() != 2 || positions.cols() < 2 ||
        positions.rows() != mesh.num_vertices()) {
        throw InvalidArgumentError("remove_branch_points: a triangle mesh and #V x 2 positions");
    }
    Eigen::MatrixXd result = positions;
    if (points.empty()) return result;
    const Index nv = mesh.num_vertices();
    const std::size_t np = points.size();
    std::vector<Complex> w(np);
    std::vector<double> exponent(np);  // (tau - 1) / tau
    for (std::size_t k = 0; k < np; ++k) {
        w[k] = {points[k].image.x(), points[k].image.y()};
        exponent[k] = double(points[k].turning - 1) / double(points[k].turning);
    }
    // Neighbours of each vertex, from the edge list.
    std::vector<Index> begin(nv + 1, 0), neighbours(2 * topology.edges.size());
    for (const auto& e : topology.edges) ++begin[e[0] + 1], ++begin[e[1] + 1];
    for (Index v = 0; v < nv; ++v) begin[v + 1] += begin[v];
    std::vector<Index> fill(begin.begin(), begin.end() - 1);
    for (const auto& e : topology.edges)
        neighbours[fill[e[0]]++] = e[1], neighbours[fill[e[1]]++] = e[0];

    std::vector<double> distance(nv, kInfinity);
    for (Index v = 0; v < nv; ++v) {
        for (const Complex& c : w)
            distance[v] = std::min(distance[v], std::abs(at(positions, v) - c));
    }
    // Per vertex: G(f_v) and the argument of f_v - w_k, followed continuously from the root.
    std::vector<Complex> g(nv, 0.0);
    std::vector<double> argument(std::size_t(nv) * np, 0.0);
    std::vector<unsigned char> reached(nv, 0);
    std::priority_queue<std::pair<double, Index>> queue;  // farthest first
    for (Index root = 0; root < nv; ++root) {
        if (reached[root] || !topology.used_vertex[root]) continue;
        // One tree per connected part, from its vertex farthest from every w_k.
        std::vector<Index> part{root};
        reached[root] = 1;
        for (std::size_t i = 0; i < part.size(); ++i) {
            for (Index j = begin[part[i]]; j < begin[part[i] + 1]; ++j) {
                if (!reached[neighbours[j]])
                    reached[neighbours[j]] = 1, part.push_back(neighbours[j]);
            }
        }
        const Index first = *std::max_element(
            part.begin(), part.end(), [&](Index a, Index b) { return distance[a] < distance[b]; });
        for (Index v : part) reached[v] = 0;
        reached[first] = 1;
        g[first] = at(positions, first);
        for (std::size_t k = 0; k < np; ++k)
            argument[first * np + k] = std::arg(at(positions, first) - w[k]);
        queue.emplace(distance[first], first);
        while (!queue.empty()) {
            const Index u = queue.top().second;
            queue.pop();
            const Complex fu = at(positions, u);
            for (Index j = begin[u]; j < begin[u + 1]; ++j) {
                const Index v = neighbours[j];
                if (reached[v]) continue;
                reached[v] = 1;
                const Complex fv = at(positions, v), mid = 0.5 * (fu + fv);
                // log G'(w) = -sum_k e_k log(w - w_k), at u, the midpoint and v, each argument
                // continued from u; Simpson's rule along the edge.
                Complex log_u = 0.0, log_mid = 0.0, log_v = 0.0;
                for (std::size_t k = 0; k < np; ++k) {
                    const double from = argument[u * np + k];
                    const Complex du = fu - w[k], dm = mid - w[k], dv = fv - w[k];
                    const double at_v = from + turn(du, dv);
                    log_u -= exponent[k] * Complex(std::log(std::abs(du)), from);
                    log_mid -= exponent[k] * Complex(std::log(std::abs(dm)), from + turn(du, dm));
                    log_v -= exponent[k] * Complex(std::log(std::abs(dv)), at_v);
                    argument[v * np + k] = at_v;
                }
                g[v] = g[u] + (fv - fu) / 6.0 *
                                  (std::exp(log_u) + 4.0 * std::exp(log_mid) + std::exp(log_v));
                queue.emplace(distance[v], v);
            }
        }
    }
    // Back to the start's bounding box: G is defined up to a similarity.
    Eigen::MatrixXd composed(nv, 2);
    std::vector<Index> used;
    for (Index v = 0; v < nv; ++v) {
        composed.row(v) << g[v].real(), g[v].imag();
        if (topology.used_vertex[v]) used.push_back(v);
    }
    if (used.empty()) return result;
    Eigen::MatrixXd before(used.size(), 2), after(used.size(), 2);
    for (std::size_t i = 0; i < used.size(); ++i) {
        before.row(i) = positions.row(used[i]).head<2>();
        after.row(i) = composed.row(used[i]);
    }
    const double scale = bounding_box_diagonal(before) / bounding_box_diagonal(after);
    const Eigen::RowVector2d from = 0.5 * (after.colwise().minCoeff() + after.colwise().maxCoeff()),
                             to = 0.5 * (before.colwise().minCoeff() + before.colwise().maxCoeff());
    for (Index v : used) result.row(v).head<2>() = (composed.row(v) - from) * scale + to;
    return result;
}

}  // namespace sa
