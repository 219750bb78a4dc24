#include "geometry/maps/initial_maps.h"

#include <Eigen/Geometry>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>

#include "geometry/maps/harmonic_map.h"
#include "geometry/mesh/boundary_loops.h"
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
    // Unknowns: u of every vertex but the pins, then v in the same order.
    std::vector<Index> free_index(nv, -1);
    Index nf = 0;
    for (Index v = 0; v < nv; ++v) {
        if (v != a && v != b) free_index[v] = nf++;
    }

    // The LSCM energy sum_t area_t ((A00 - A11)^2 + (A10 + A01)^2) = sum_t area_t (|A|^2 -
    // 2 det A) is the Dirichlet energy of u plus that of v, less twice the signed area of the
    // image; a triangle's signed area is a sum over its edges, and the terms of an edge shared by
    // two triangles of the same orientation cancel:
    //   E = u^T L u + v^T L v - sum_{edges i->j} sigma_t (u_i v_j - u_j v_i),
    // with L the cotangent Laplacian (L_ij = -(cot a_ij + cot b_ij) / 2), the sum over the edges
    // of the boundary (and between triangles oriented differently in the plane), directed as
    // their triangle t lists them, and sigma_t = +-1 the orientation of t (+1 in space).
    // Assembled per triangle, the u-v products of every interior edge cancel only in value: they
    // would stay in the pattern and couple u and v everywhere (twice the entries per row, about
    // eight times the factorization's flops). Here u and v are coupled on the boundary only, and
    // the lower triangle is written column by column from the edges (no triplets, no rest frames:
    // a quarter of the memory, which on a million triangles is most of this function's time).
    const bool planar = mesh.ambient_dimension() == 2;
    auto corner_cotangent = [&](Index s, int k) {  // cot of the angle at local corner k
        const Eigen::Vector3d p = mesh.point(mesh.simplices(s, k));
        const Eigen::Vector3d e1 = mesh.point(mesh.simplices(s, (k + 1) % 3)) - p,
                              e2 = mesh.point(mesh.simplices(s, (k + 2) % 3)) - p;
        const double area2 = e1.cross(e2).norm();
        if (!(area2 > 0.0)) {
            throw InvalidArgumentError("lscm: triangle " + std::to_string(s) +
                                       " has no area in the rest mesh");
        }
        return e1.dot(e2) / area2;
    };
    auto orientation = [&](Index s) -> int {
        if (!planar) return 1;
        const Eigen::Vector3d p = mesh.point(mesh.simplices(s, 0));
        return (mesh.point(mesh.simplices(s, 1)) - p)
                           .cross(mesh.point(mesh.simplices(s, 2)) - p)
                           .z() > 0.0
                   ? 1
                   : -1;
    };
    struct WeightedEdge {
        Index a, b;  // a < b
        double w;    // (cot a_ab + cot b_ab) / 2 = -L_ab
    };
    std::vector<WeightedEdge> edges;
    edges.reserve(topology.interior_facets.size() + topology.boundary_facets.size());
    for (const InteriorFacet& f : topology.interior_facets) {
        edges.push_back({f.vertices[0], f.vertices[1],
                         0.5 * (corner_cotangent(f.simplex[0], f.opposite[0]) +
                                corner_cotangent(f.simplex[1], f.opposite[1]))});
    }
    for (const BoundaryFacet& f : topology.boundary_facets)
        edges.push_back(
            {f.vertices[0], f.vertices[1], 0.5 * corner_cotangent(f.simplex, f.opposite)});
    // Coupling of u_i and v_j: entries (row v_j, column u_i) of the lower triangle, or
    // right-hand side terms where a pin is involved.
    struct Coupling {
        Index row, col;
        double value;
    };
    std::vector<Coupling> coupling;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * nf);
    // H[u_i][v_j] = H[v_j][u_i] += h (the energy q^T H q gains 2 h u_i v_j).
    auto couple = [&](Index i, Index j, double h) {
        const Index fi = free_index[i], fj = free_index[j];
        if (fi >= 0 && fj >= 0) {
            coupling.push_back({nf + fj, fi, h});
        } else if (fi >= 0) {
            rhs[fi] -= h * x(j, 1);
        } else if (fj >= 0) {
            rhs[nf + fj] -= h * x(i, 0);
        }
    };
    auto add_area_term = [&](Index s, int k) {
        // Edge i -> j (opposite corner k): -sigma_t (u_i v_j - u_j v_i).
        const Index i = mesh.simplices(s, (k + 1) % 3), j = mesh.simplices(s, (k + 2) % 3);
        const double h = -0.5 * orientation(s);
        couple(i, j, h);
        couple(j, i, -h);
    };
    for (const BoundaryFacet& f : topology.boundary_facets) add_area_term(f.simplex, f.opposite);
    if (planar) {
        for (const InteriorFacet& f : topology.interior_facets) {
            if (orientation(f.simplex[0]) == orientation(f.simplex[1])) continue;
            add_area_term(f.simplex[0], f.opposite[0]);
            add_area_term(f.simplex[1], f.opposite[1]);
        }
    }
    std::sort(coupling.begin(), coupling.end(), [](const Coupling& p, const Coupling& q) {
        return p.col != q.col ? p.col < q.col : p.row < q.row;
    });
    std::size_t merged = 0;  // couplings of one pair (from triangles on both sides) summed
    for (const Coupling& c : coupling) {
        if (merged > 0 && coupling[merged - 1].row == c.row && coupling[merged - 1].col == c.col) {
            coupling[merged - 1].value += c.value;
        } else {
            coupling[merged++] = c;
        }
    }
    coupling.resize(merged);

    // Column counts: the diagonal, the neighbours of larger index, and (u columns) couplings.
    const Index n = 2 * nf;
    std::vector<int> begin(n + 1, 0);
    for (Index f = 0; f < n; ++f) begin[f + 1] = 1;
    for (const WeightedEdge& e : edges) {
        const Index fa = free_index[e.a], fb = free_index[e.b];
        if (fa < 0 || fb < 0) continue;
        const Index column = std::min(fa, fb);
        ++begin[column + 1];
        ++begin[nf + column + 1];
    }
    for (const Coupling& c : coupling) ++begin[c.col + 1];
    for (Index f = 0; f < n; ++f) begin[f + 1] += begin[f];
    Eigen::SparseMatrix<double> lower(n, n);
    lower.resizeNonZeros(begin[n]);
    int* outer = lower.outerIndexPtr();
    int* rows = lower.innerIndexPtr();
    double* values = lower.valuePtr();
    std::copy(begin.begin(), begin.end(), outer);
    std::vector<int> cursor(begin.begin(), begin.end() - 1);
    for (Index f = 0; f < n; ++f) {
        rows[cursor[f]] = static_cast<int>(f);
        values[cursor[f]++] = 0.0;
    }
    for (const WeightedEdge& e : edges) {
        const Index fa = free_index[e.a], fb = free_index[e.b];
        for (int c = 0; c < 2; ++c) {  // L_ab in the u block, then the v block
            if (fa >= 0) values[begin[fa + c * nf]] += e.w;
            if (fb >= 0) values[begin[fb + c * nf]] += e.w;
            if (fa >= 0 && fb >= 0) {
                const Index column = std::min(fa, fb) + c * nf;
                rows[cursor[column]] = static_cast<int>(std::max(fa, fb) + c * nf);
                values[cursor[column]++] = -e.w;
            } else if (fa >= 0) {
                rhs[fa + c * nf] += e.w * x(e.b, c);
            } else if (fb >= 0) {
                rhs[fb + c * nf] += e.w * x(e.a, c);
            }
        }
    }
    edges = {};
    for (const Coupling& c : coupling) {
        rows[cursor[c.col]] = static_cast<int>(c.row);
        values[cursor[c.col]++] = c.value;
    }
    // Rows in order within each column (a few entries each).
    std::vector<std::pair<int, double>> column_entries;
    for (Index f = 0; f < n; ++f) {
        column_entries.clear();
        for (int p = begin[f]; p < begin[f + 1]; ++p)
            column_entries.emplace_back(rows[p], values[p]);
        std::sort(column_entries.begin(), column_entries.end());
        for (std::size_t k = 0; k < column_entries.size(); ++k) {
            rows[begin[f] + k] = column_entries[k].first;
            values[begin[f] + k] = column_entries[k].second;
        }
    }
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
