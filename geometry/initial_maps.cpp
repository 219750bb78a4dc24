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

namespace {

/// `mesh` multiplied by 2^-k, k = scale_exponent(): the initial maps are computed at unit scale
/// (on a mesh at 1e200 its areas overflowed), with the same bits as at the mesh's own scale.
SimplicialMesh at_unit_scale(const SimplicialMesh& mesh, int k) {
    SimplicialMesh scaled = mesh;
    scaled.vertices = mesh.vertices * std::ldexp(1.0, -k);
    return scaled;
}

}  // namespace

Eigen::MatrixXd harmonic_circle(const SimplicialMesh& mesh, const MeshTopology& topology) {
    if (const int k = scale_exponent(mesh.vertices); k != 0)
        return harmonic_circle(at_unit_scale(mesh, k), topology);  // on the unit circle anyway
    const std::vector<Index> loop = the_loop(mesh, topology);
    return harmonic_map(mesh, loop, circle_boundary(mesh, loop), LaplacianWeights::kCotangent);
}

Eigen::MatrixXd tutte_embedding(const SimplicialMesh& mesh, const MeshTopology& topology,
                                TutteWeights weights) {
    if (const int k = scale_exponent(mesh.vertices); k != 0)
        return tutte_embedding(at_unit_scale(mesh, k), topology, weights);  // on the unit circle
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
    if (const int k = scale_exponent(mesh.vertices); k != 0)
        return lscm(at_unit_scale(mesh, k), topology) * std::ldexp(1.0, k);  // in mesh units
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
    const Index nv = mesh.num_vertices();
    Eigen::MatrixXd x = Eigen::MatrixXd::Zero(nv, 2);
    x.row(b) << (mesh.point(b) - mesh.point(a)).norm(), 0.0;
    // Unknowns: (u_v, v_v) of every vertex but the pins, interleaved.
    std::vector<Index> free_index(nv, -1);
    Index nf = 0;
    for (Index v = 0; v < nv; ++v) {
        if (v != a && v != b) free_index[v] = nf++;
    }
    const RestFrames<2> frames = rest_frames<2>(mesh);
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * nf);
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        // A = [p1 - p0, p2 - p0] R^-1 with p_k = (u_k, v_k): the LSCM residuals
        // r1 = A00 - A11 and r2 = A10 + A01 are linear in the 6 coordinates: r = C q.
        const Mat<2>& R = frames.edge_inverse[s];
        Eigen::Matrix<double, 2, 6> C = Eigen::Matrix<double, 2, 6>::Zero();
        for (int k = 0; k < 2; ++k) {  // edge k: p_{k+1} - p_0, weights R(k, c) for column c of A
            const int vertex = k + 1;
            // A00 = sum_k (u_{k+1} - u_0) R(k,0); A11 = sum_k (v_{k+1} - v_0) R(k,1)
            // A10 = sum_k (v_{k+1} - v_0) R(k,0); A01 = sum_k (u_{k+1} - u_0) R(k,1)
            C(0, 2 * vertex) += R(k, 0);
            C(0, 0) -= R(k, 0);
            C(0, 2 * vertex + 1) -= R(k, 1);
            C(0, 1) += R(k, 1);
            C(1, 2 * vertex + 1) += R(k, 0);
            C(1, 1) -= R(k, 0);
            C(1, 2 * vertex) += R(k, 1);
            C(1, 0) -= R(k, 1);
        }
        const Eigen::Matrix<double, 6, 6> H = frames.volume[s] * C.transpose() * C;
        Index index[6];
        for (int k = 0; k < 3; ++k) {
            const Index v = mesh.simplices(s, k);
            index[2 * k] = free_index[v] < 0 ? -1 : 2 * free_index[v];
            index[2 * k + 1] = free_index[v] < 0 ? -1 : 2 * free_index[v] + 1;
        }
        for (int r = 0; r < 6; ++r) {
            if (index[r] < 0) continue;
            for (int c = 0; c < 6; ++c) {
                if (index[c] >= 0) {
                    if (index[c] <= index[r]) entries.emplace_back(index[r], index[c], H(r, c));
                } else {
                    const Index v = mesh.simplices(s, c / 2);
                    rhs[index[r]] -= H(r, c) * x(v, c % 2);
                }
            }
        }
    }
    Eigen::SparseMatrix<double> lower(2 * nf, 2 * nf);
    lower.setFromTriplets(entries.begin(), entries.end());
    LinearSolver solver(LinearSolverType::kCholmodSupernodal,
                        FillOrdering::kAmd);  // one factorization
    solver.analyze(lower);
    if (solver.factorize(lower) != FactorizationStatus::kSuccess) {
        throw InvalidArgumentError("lscm: the system is singular (is the mesh connected?)");
    }
    const Eigen::VectorXd solution = solver.solve(rhs);
    for (Index v = 0; v < nv; ++v) {
        if (free_index[v] >= 0)
            x.row(v) << solution[2 * free_index[v]], solution[2 * free_index[v] + 1];
    }
    return x;
}

}  // namespace sa
