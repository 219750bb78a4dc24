#include "geometry/initial_maps.h"

#include <Eigen/Geometry>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <cmath>

#include "geometry/boundary_loops.h"
#include "geometry/harmonic_map.h"
#include "geometry/rest_frames.h"
#include "optim/errors.h"
#include "optim/linear_solver.h"

namespace sa {

namespace {

std::vector<Index> the_loop(const SimplicialMesh& mesh, const MeshTopology& topology) {
    const auto loops = boundary_loops(mesh, topology);
    if (loops.size() != 1) {
        throw InvalidArgumentError("initial map: the mesh has " + std::to_string(loops.size()) +
                                   " boundary loops, a disk has one");
    }
    return loops.front();
}

}  // namespace

Eigen::MatrixXd circle_boundary(const SimplicialMesh& mesh, const std::vector<Index>& loop) {
    const std::size_t n = loop.size();
    std::vector<double> length(n + 1, 0.0);
    for (std::size_t k = 0; k < n; ++k)
        length[k + 1] = length[k] + (mesh.point(loop[(k + 1) % n]) - mesh.point(loop[k])).norm();
    Eigen::MatrixXd circle(n, 2);
    for (std::size_t k = 0; k < n; ++k) {
        const double angle = 2.0 * M_PI * length[k] / length[n];
        circle.row(k) << std::cos(angle), std::sin(angle);
    }
    return circle;
}

Eigen::MatrixXd harmonic_circle(const SimplicialMesh& mesh, const MeshTopology& topology) {
    const std::vector<Index> loop = the_loop(mesh, topology);
    return harmonic_map(mesh, loop, circle_boundary(mesh, loop), LaplacianWeights::kCotangent);
}

Eigen::MatrixXd tutte_embedding(const SimplicialMesh& mesh, const MeshTopology& topology,
                                TutteWeights weights) {
    const std::vector<Index> loop = the_loop(mesh, topology);
    const Eigen::MatrixXd circle = circle_boundary(mesh, loop);
    if (weights == TutteWeights::kUniform)
        return harmonic_map(mesh, loop, circle, LaplacianWeights::kUniform);

    // Mean-value weights: w_ij = (tan(a/2) + tan(b/2)) / |v_i - v_j|, a and b the angles at v_i
    // of the two triangles beside edge ij. Not symmetric: row i is normalized by sum_j w_ij.
    const Index nv = mesh.num_vertices();
    std::vector<Index> free_index(nv, -1);
    std::vector<unsigned char> on_loop(nv, 0);
    for (Index v : loop) on_loop[v] = 1;
    Index nf = 0;
    for (Index v = 0; v < nv; ++v) {
        if (!on_loop[v]) free_index[v] = nf++;
    }
    Eigen::MatrixXd x = Eigen::MatrixXd::Zero(nv, 2);
    for (std::size_t k = 0; k < loop.size(); ++k) x.row(loop[k]) = circle.row(k);
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nf, 2);
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        for (int k = 0; k < 3; ++k) {
            const Index i = mesh.simplices(s, k);
            const Index fi = free_index[i];
            if (fi < 0) continue;
            const Index j = mesh.simplices(s, (k + 1) % 3), l = mesh.simplices(s, (k + 2) % 3);
            const Eigen::Vector3d eij = mesh.point(j) - mesh.point(i),
                                  eil = mesh.point(l) - mesh.point(i);
            const double angle = std::atan2(eij.cross(eil).norm(), eij.dot(eil));
            const double t = std::tan(0.5 * angle);
            // This triangle contributes t to w_ij and to w_il.
            for (auto [other, length] : {std::pair{j, eij.norm()}, std::pair{l, eil.norm()}}) {
                const double w = t / length;
                entries.emplace_back(fi, fi, w);
                if (free_index[other] >= 0) {
                    entries.emplace_back(fi, free_index[other], -w);
                } else {
                    rhs.row(fi) += w * x.row(other);
                }
            }
        }
    }
    if (nf == 0) return x;
    Eigen::SparseMatrix<double> system(nf, nf);
    system.setFromTriplets(entries.begin(), entries.end());
    system.makeCompressed();
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(system);
    if (lu.info() != Eigen::Success)
        throw InvalidArgumentError("tutte_embedding: the mean-value system is singular");
    const Eigen::MatrixXd solution = lu.solve(rhs);
    for (Index v = 0; v < nv; ++v) {
        if (free_index[v] >= 0) x.row(v) = solution.row(free_index[v]);
    }
    return x;
}

Eigen::MatrixXd lscm(const SimplicialMesh& mesh, const MeshTopology& topology) {
    const std::vector<Index> loop = the_loop(mesh, topology);
    // Pins: a boundary vertex farthest from the loop's first vertex, then one farthest from it.
    auto farthest = [&](Index from) {
        Index best = loop.front();
        for (Index v : loop) {
            if ((mesh.point(v) - mesh.point(from)).norm() >
                (mesh.point(best) - mesh.point(from)).norm())
                best = v;
        }
        return best;
    };
    const Index a = farthest(loop.front()), b = farthest(a);
    const Index nv = mesh.num_vertices(), ns = mesh.num_simplices();
    Eigen::MatrixXd x = Eigen::MatrixXd::Zero(nv, 2);
    x.row(b) << (mesh.point(b) - mesh.point(a)).norm(), 0.0;
    // Unknowns: u of every vertex but the pins, then v in the same order.
    std::vector<Index> free_index(nv, -1);
    Index nf = 0;
    for (Index v = 0; v < nv; ++v) {
        if (v != a && v != b) free_index[v] = nf++;
    }
    const RestFrames<2> frames = rest_frames<2>(mesh);

    // The LSCM energy sum_t area_t ((A00 - A11)^2 + (A10 + A01)^2) = sum_t area_t (|A|^2 -
    // 2 det A) is the Dirichlet energy of u plus that of v, less twice the signed area of the
    // image; a triangle's signed area is a sum over its edges, and the terms of an edge shared by
    // two triangles of the same orientation cancel:
    //   E = u^T L u + v^T L v - sum_{edges i->j} sigma_t (u_i v_j - u_j v_i),
    // with L the cotangent Laplacian (sum_t area_t |grad u|^2), the sum over the edges of the
    // boundary (and between triangles whose rest frames are oriented differently), directed as
    // their triangle t lists them, and sigma_t = +-1 the orientation of t's rest frame.
    // Assembled per triangle, the u-v products of every interior edge cancel only in value: they
    // would stay in the pattern and couple u and v everywhere (twice the entries per row, about
    // eight times the factorization's flops). Here u and v are coupled on the boundary only.
    std::vector<signed char> sigma(ns);
    for (Index s = 0; s < ns; ++s) sigma[s] = frames.edge_inverse[s].determinant() > 0.0 ? 1 : -1;
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(std::size_t(ns) * 12 + 4 * loop.size());
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * nf);
    // Adds q_r^T H q_c to the energy's bilinear form, for unknowns or pinned values; the system
    // is H_ff q_f = -H_fp q_p (H symmetric, its lower triangle stored).
    auto add = [&](Index row_vertex, int row_coordinate, Index col_vertex, int col_coordinate,
                   double value) {
        const Index fr = free_index[row_vertex], fc = free_index[col_vertex];
        if (fr < 0) return;
        const Index r = fr + row_coordinate * nf;
        if (fc < 0) {
            rhs[r] -= value * x(col_vertex, col_coordinate);
            return;
        }
        const Index c = fc + col_coordinate * nf;
        if (c <= r) entries.emplace_back(r, c, value);
    };
    for (Index s = 0; s < ns; ++s) {
        // grad u = sum_k u_k g_k: A = [p1 - p0, p2 - p0] R^-1, so g_1, g_2 are R's rows.
        const Mat<2>& R = frames.edge_inverse[s];
        Eigen::Vector2d g[3];
        g[1] = R.row(0).transpose();
        g[2] = R.row(1).transpose();
        g[0] = -g[1] - g[2];
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                const double w = frames.volume[s] * g[i].dot(g[j]);
                for (int c = 0; c < 2; ++c)
                    add(mesh.simplices(s, i), c, mesh.simplices(s, j), c, w);
            }
        }
        for (int k = 0; k < 3; ++k) {
            const Index other = topology.neighbour_of(s, k);
            if (other >= 0 && sigma[other] == sigma[s]) continue;
            // Edge i -> j (opposite corner k): -sigma_t (u_i v_j - u_j v_i), symmetrized.
            const Index i = mesh.simplices(s, (k + 1) % 3), j = mesh.simplices(s, (k + 2) % 3);
            const double h = -0.5 * sigma[s];
            add(i, 0, j, 1, h);
            add(j, 1, i, 0, h);
            add(j, 0, i, 1, -h);
            add(i, 1, j, 0, -h);
        }
    }
    Eigen::SparseMatrix<double> lower(2 * nf, 2 * nf);
    lower.setFromTriplets(entries.begin(), entries.end());
    entries = {};
    LinearSolver solver(LinearSolverType::kCholmodSupernodal,
                        FillOrdering::kAmd);  // one factorization
    solver.analyze(lower);
    if (solver.factorize(lower) != FactorizationStatus::kSuccess) {
        throw InvalidArgumentError("lscm: the system is singular (is the mesh connected?)");
    }
    const Eigen::VectorXd solution = solver.solve(rhs);
    for (Index v = 0; v < nv; ++v) {
        if (free_index[v] >= 0) x.row(v) << solution[free_index[v]], solution[free_index[v] + nf];
    }
    return x;
}

}  // namespace sa
