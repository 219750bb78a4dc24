#include "frontends/polycube/cube_cover.h"

#include <Eigen/Sparse>
#include <cmath>
#include <limits>
#include <numeric>

#include "frontends/polycube/polycube_planes.h"
#include "geometry/detail/union_find.h"
#include "optim/errors.h"
#include "optim/linear_solver.h"

namespace sa {

namespace {

/// Gradients of the four barycentric functions of tetrahedron t (columns) and its volume.
Eigen::Matrix<double, 3, 4> barycentric_gradients(const SimplicialMesh& mesh, Index t,
                                                  double* volume) {
    Eigen::Matrix3d edges;
    const Eigen::Vector3d p0 = mesh.vertices.row(mesh.simplices(t, 0)).transpose();
    for (int k = 0; k < 3; ++k) {
        edges.col(k) = mesh.vertices.row(mesh.simplices(t, k + 1)).transpose() - p0;
    }
    *volume = std::abs(edges.determinant()) / 6.0;
    // x = p0 + edges * lambda_{1..3}: grad lambda_k = row k of edges^-1.
    const Eigen::Matrix3d inverse = edges.inverse();
    Eigen::Matrix<double, 3, 4> g;
    g.rightCols<3>() = inverse.transpose();
    g.col(0) = -g.rightCols<3>().rowwise().sum();
    return g;
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// Minimum length of a PolyCube edge in the cube cover, as a fraction of its rest extent.
constexpr double kMinimumEdgeFraction = 0.5;
/// Solves per axis at most: edges still out of order after them are left to the untangling.
constexpr int kMaxSolves = 20;

/// The cube cover's coordinate along `axis` (#V): the Dirichlet energy of x - p_axis minimized
/// with every plane of that axis at one coordinate, plane p at tie_offset[p] from tie_root[p]
/// (chains of ties end at a plane that is its own root), shifted so that each connected
/// component keeps its volume-weighted mean. Vertices with a finite `pinned` value (empty: none)
/// take it (before that shift) instead of being solved for.
Eigen::VectorXd solve_axis(const SimplicialMesh& mesh,
                           const std::vector<Eigen::Matrix<double, 3, 4>>& gradients,
                           const std::vector<double>& volume, const std::vector<int>& component,
                           const PolycubePlanes& planes, int axis, const std::vector<int>& tie_root,
                           const std::vector<double>& tie_offset,
                           const Eigen::VectorXd& pinned = {}) {
    const Index nv = mesh.num_vertices(), nt = mesh.num_simplices();
    // Unknowns: one per free vertex, one per tied set of planes; x_v = unknown + offset[v], or
    // offset[v] alone for a pinned vertex (unknown -1).
    std::vector<Index> unknown(nv, -1), unknown_of_root(planes.size(), -1);
    Eigen::VectorXd offset = Eigen::VectorXd::Zero(nv);
    std::vector<unsigned char> component_pinned(nv, 0);
    Index n = 0;
    for (Index v = 0; v < nv; ++v) {
        if (pinned.size() > 0 && std::isfinite(pinned[v])) {
            offset[v] = pinned[v];
            component_pinned[component[v]] = 1;
            continue;
        }
        int p = planes.plane_of_vertex[v][axis];
        if (p < 0) {
            unknown[v] = n++;
            continue;
        }
        while (tie_root[p] != p) {
            offset[v] += tie_offset[p];
            p = tie_root[p];
        }
        if (unknown_of_root[p] < 0) unknown_of_root[p] = n++;
        unknown[v] = unknown_of_root[p];
    }
    // One unknown per component without pinned vertices is held at 0 (the energy does not see
    // translations); the solution is shifted afterwards.
    std::vector<unsigned char> held(n, 0);
    {
        std::vector<unsigned char> seen(component_pinned);
        for (Index v = 0; v < nv; ++v) {
            if (unknown[v] >= 0 && !seen[component[v]]) {
                seen[component[v]] = 1;
                held[unknown[v]] = 1;
            }
        }
    }
    std::vector<Index> row(n, -1);
    Index m = 0;
    for (Index i = 0; i < n; ++i) {
        if (!held[i]) row[i] = m++;
    }
    // sum_T vol |G x_T - e_a|^2 = y^T K y - 2 y^T (b - K offset) + const, K_T = vol G^T G,
    // b_T = vol G^T e_a.
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(16 * std::size_t(nt));
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
    for (Index t = 0; t < nt; ++t) {
        const Eigen::Matrix4d K = volume[t] * gradients[t].transpose() * gradients[t];
        const Eigen::Vector4d b = volume[t] * gradients[t].row(axis).transpose();
        Eigen::Vector4d o;
        for (int i = 0; i < 4; ++i) o[i] = offset[mesh.simplices(t, i)];
        const Eigen::Vector4d r = b - K * o;
        auto row_of = [&](int i) {
            const Index u = unknown[mesh.simplices(t, i)];
            return u < 0 ? Index(-1) : row[u];
        };
        for (int i = 0; i < 4; ++i) {
            const Index ri = row_of(i);
            if (ri < 0) continue;
            rhs[ri] += r[i];
            for (int j = 0; j < 4; ++j) {
                const Index rj = row_of(j);
                if (rj >= 0 && rj <= ri) entries.emplace_back(ri, rj, K(i, j));
            }
        }
    }
    Eigen::VectorXd solution = Eigen::VectorXd::Zero(n);
    if (m > 0) {
        Eigen::SparseMatrix<double> lower(m, m);
        lower.setFromTriplets(entries.begin(), entries.end());
        LinearSolver solver(LinearSolverType::kCholmodSupernodal, FillOrdering::kAmd);
        solver.analyze(lower);
        if (solver.factorize(lower) != FactorizationStatus::kSuccess) {
            throw InvalidArgumentError(
                "cube_cover_map: the least-squares system is singular (a rest tetrahedron is "
                "degenerate?)");
        }
        const Eigen::VectorXd y = solver.solve(rhs);
        for (Index i = 0; i < n; ++i) {
            if (row[i] >= 0) solution[i] = y[row[i]];
        }
    }
    Eigen::VectorXd x(nv);
    for (Index v = 0; v < nv; ++v) x[v] = (unknown[v] < 0 ? 0.0 : solution[unknown[v]]) + offset[v];
    // Shift each component so that its volume-weighted mean is the rest one.
    std::vector<double> shift(nv, 0.0), weight(nv, 0.0);
    for (Index t = 0; t < nt; ++t) {
        const Index c = component[mesh.simplices(t, 0)];
        for (int i = 0; i < 4; ++i) {
            const Index v = mesh.simplices(t, i);
            shift[c] += 0.25 * volume[t] * (mesh.vertices(v, axis) - x[v]);
            weight[c] += 0.25 * volume[t];
        }
    }
    for (Index v = 0; v < nv; ++v) {
        if (weight[component[v]] > 0.0) x[v] += shift[component[v]] / weight[component[v]];
    }
    return x;
}

}  // namespace

CubeCover cube_cover_map(const SimplicialMesh& mesh, const TetBoundary& boundary,
                         const PolycubeCharts& charts) {
    if (static_cast<Index>(charts.chart_of.size()) != boundary.size()) {
        throw InvalidArgumentError("cube_cover_map: the charts are not those of this boundary");
    }
    const Index nv = mesh.num_vertices(), nt = mesh.num_simplices();
    std::vector<Eigen::Matrix<double, 3, 4>> gradients(nt);
    std::vector<double> volume(nt);
    for (Index t = 0; t < nt; ++t) gradients[t] = barycentric_gradients(mesh, t, &volume[t]);

    // Connected components of vertices over tetrahedra, for the translation of each.
    UnionFind components(nv);
    for (Index t = 0; t < nt; ++t) {
        for (int k = 1; k < 4; ++k) components.join(mesh.simplices(t, 0), mesh.simplices(t, k));
    }
    std::vector<int> component(nv);
    for (Index v = 0; v < nv; ++v) component[v] = components.find(v);

    const PolycubePlanes planes = polycube_planes(boundary, charts, nv);
    const std::vector<PolycubeEdgeOrder> orders =
        polycube_edge_orders(boundary, charts, planes, mesh.vertices);

    CubeCover cover;
    cover.positions = mesh.vertices;
    cover.chart_coordinate.assign(charts.size(), 0.0);
    for (const PolycubeEdgeOrder& e : orders) {
        ++cover.edge_orders;
        if (e.from_plane == e.to_plane) ++cover.collapsed_edges;
    }
    for (int axis = 0; axis < 3; ++axis) {
        // Ties between planes of this axis: plane p sits at tie_offset[p] from its tie root.
        std::vector<int> tie_root(planes.size());
        std::iota(tie_root.begin(), tie_root.end(), 0);
        std::vector<double> tie_offset(planes.size(), 0.0);
        auto root_of = [&](int p, double* offset) {
            *offset = 0.0;
            while (tie_root[p] != p) {
                *offset += tie_offset[p];
                p = tie_root[p];
            }
            return p;
        };
        Eigen::VectorXd x;
        for (int pass = 0;; ++pass) {
            x = solve_axis(mesh, gradients, volume, component, planes, axis, tie_root, tie_offset);
            // The edges along this axis whose corners' planes are out of rest order, or closer
            // than half their rest extent: tie their planes at that distance and solve again.
            bool tied = false;
            for (const PolycubeEdgeOrder& e : orders) {
                if (pass + 1 == kMaxSolves) break;
                if (e.axis != axis || e.from_plane == e.to_plane) continue;
                const double wanted = kMinimumEdgeFraction * e.rest_extent;
                if (x[e.to] - x[e.from] >= wanted * (1.0 - 1e-9)) continue;
                double from_offset, to_offset;
                const int a = root_of(e.from_plane, &from_offset);
                const int b = root_of(e.to_plane, &to_offset);
                if (a == b) continue;  // tied already, at a distance that falls short
                // c_to = c_from + wanted: c_b + to_offset = c_a + from_offset + wanted.
                tie_root[b] = a;
                tie_offset[b] = from_offset + wanted - to_offset;
                ++cover.lengthened_edges;
                tied = true;
            }
            if (!tied) break;
        }
        // The vertices of every edge along this axis in their order between its corners, spaced
        // as at rest (arc length): a vertex on two planes moves only along their line, so one
        // that starts beyond its neighbour on the line could pass it only by collapsing the edge
        // between them, which no inversion-free path does. The planes keep
        // their coordinates; the rest follows the Laplacian again.
        Eigen::VectorXd pinned = Eigen::VectorXd::Constant(nv, kNaN);
        bool any = false;
        for (const PolycubeEdgeOrder& e : orders) {
            if (e.axis != axis || e.from_plane == e.to_plane || !(x[e.to] > x[e.from])) continue;
            std::vector<double> length(e.vertices.size(), 0.0);
            for (std::size_t k = 1; k < e.vertices.size(); ++k) {
                length[k] = length[k - 1] + (mesh.vertices.row(e.vertices[k]) -
                                             mesh.vertices.row(e.vertices[k - 1]))
                                                .norm();
            }
            for (std::size_t k = 1; k + 1 < e.vertices.size(); ++k) {
                pinned[e.vertices[k]] =
                    x[e.from] + (x[e.to] - x[e.from]) * length[k] / length.back();
                any = true;
            }
        }
        if (any) {
            for (Index v = 0; v < nv; ++v)
                if (planes.plane_of_vertex[v][axis] >= 0) pinned[v] = x[v];
            x = solve_axis(mesh, gradients, volume, component, planes, axis, tie_root, tie_offset,
                           pinned);
        }
        for (const PolycubeEdgeOrder& e : orders) {
            if (e.axis == axis && e.from_plane != e.to_plane &&
                !(x[e.to] - x[e.from] > 0.5 * kMinimumEdgeFraction * e.rest_extent))
                ++cover.unordered_edges;
        }
        cover.positions.col(axis) = x;
        for (int c = 0; c < charts.size(); ++c) {
            if (label_axis(charts.label[c]) == axis) {
                cover.chart_coordinate[c] = x[boundary.triangles(charts.members[c].front(), 0)];
            }
        }
        double energy = 0.0;
        for (Index t = 0; t < nt; ++t) {
            Eigen::Vector4d xt;
            for (int i = 0; i < 4; ++i) xt[i] = x[mesh.simplices(t, i)];
            Eigen::Vector3d g = gradients[t] * xt;
            g[axis] -= 1.0;
            energy += volume[t] * g.squaredNorm();
        }
        cover.energy[axis] = energy;
    }
    return cover;
}

}  // namespace sa
