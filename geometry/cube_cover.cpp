#include "geometry/cube_cover.h"

#include <Eigen/Sparse>
#include <numeric>

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

int find(std::vector<int>& parent, int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
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
    std::vector<int> component(nv);
    std::iota(component.begin(), component.end(), 0);
    for (Index t = 0; t < nt; ++t) {
        for (int k = 1; k < 4; ++k) {
            const int a = find(component, mesh.simplices(t, 0)),
                      b = find(component, mesh.simplices(t, k));
            if (a != b) component[std::max(a, b)] = std::min(a, b);
        }
    }
    for (Index v = 0; v < nv; ++v) component[v] = find(component, v);

    CubeCover cover;
    cover.positions = mesh.vertices;
    cover.chart_coordinate.assign(charts.size(), 0.0);
    for (int axis = 0; axis < 3; ++axis) {
        // Charts of this axis sharing a vertex form one group with one coordinate.
        std::vector<int> group(charts.size());
        std::iota(group.begin(), group.end(), 0);
        std::vector<int> chart_of_vertex(nv, -1);
        for (Index b = 0; b < boundary.size(); ++b) {
            const int c = charts.chart_of[b];
            if (label_axis(charts.label[c]) != axis) continue;
            for (int i = 0; i < 3; ++i) {
                int& mine = chart_of_vertex[boundary.triangles(b, i)];
                if (mine < 0) {
                    mine = c;
                } else {
                    const int x = find(group, mine), y = find(group, c);
                    if (x != y) group[std::max(x, y)] = std::min(x, y);
                }
            }
        }
        // Unknowns: one per free vertex, one per group.
        std::vector<Index> unknown(nv, -1), unknown_of_group(charts.size(), -1);
        Index n = 0;
        for (Index v = 0; v < nv; ++v) {
            if (chart_of_vertex[v] < 0) {
                unknown[v] = n++;
            } else {
                const int g = find(group, chart_of_vertex[v]);
                if (unknown_of_group[g] < 0) unknown_of_group[g] = n++;
                unknown[v] = unknown_of_group[g];
            }
        }
        // One unknown per component is pinned (the energy does not see translations); the
        // solution is shifted afterwards.
        std::vector<unsigned char> pinned(n, 0);
        {
            std::vector<unsigned char> seen(nv, 0);
            for (Index v = 0; v < nv; ++v) {
                if (!seen[component[v]]) {
                    seen[component[v]] = 1;
                    pinned[unknown[v]] = 1;
                }
            }
        }
        std::vector<Index> row(n, -1);
        Index m = 0;
        for (Index i = 0; i < n; ++i) {
            if (!pinned[i]) row[i] = m++;
        }
        // sum_T vol |G x_T - e_a|^2 = x^T K x - 2 x^T b + const, K_T = vol G^T G,
        // b_T = vol G^T e_a.
        std::vector<Eigen::Triplet<double>> entries;
        entries.reserve(16 * std::size_t(nt));
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
        for (Index t = 0; t < nt; ++t) {
            const Eigen::Matrix4d K = volume[t] * gradients[t].transpose() * gradients[t];
            const Eigen::Vector4d b = volume[t] * gradients[t].row(axis).transpose();
            for (int i = 0; i < 4; ++i) {
                const Index ri = row[unknown[mesh.simplices(t, i)]];
                if (ri < 0) continue;
                rhs[ri] += b[i];
                for (int j = 0; j < 4; ++j) {
                    const Index rj = row[unknown[mesh.simplices(t, j)]];
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
                    "cube_cover_map: the least-squares system is singular (a rest tetrahedron "
                    "is degenerate?)");
            }
            const Eigen::VectorXd y = solver.solve(rhs);
            for (Index i = 0; i < n; ++i) {
                if (row[i] >= 0) solution[i] = y[row[i]];
            }
        }
        Eigen::VectorXd x(nv);
        for (Index v = 0; v < nv; ++v) x[v] = solution[unknown[v]];
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
