#include "geometry/maps/initial_maps.h"

#include <Eigen/Geometry>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <complex>
#include <optional>

#include "geometry/maps/harmonic_map.h"
#include "geometry/mesh/boundary_loops.h"
#include "optim/errors.h"
#include "optim/hermitian_solve.h"
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
    // Unknowns: u + iv of every vertex but the pins.
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
    // Written as E = u^T L u + v^T L v + 2 v^T C u with C antisymmetric (nonzero on those
    // edges only), E is z^H (L + iC) z for z = u + iv: the minimizer solves one Hermitian
    // system with L's pattern (optim/hermitian_solve.h), half the unknowns of the real one and
    // a smaller factor. Its lower triangle is written column by column from the edges (no
    // triplets, no rest frames: on a million triangles memory is most of this function's time).
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
    using Complex = std::complex<double>;
    // Right-hand side r + is: r from the u rows, s from the v rows, for the pins' terms.
    Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(nf);

    // Column counts: the diagonal and the neighbours of larger index.
    std::vector<int> begin(nf + 1, 0);
    for (Index f = 0; f < nf; ++f) begin[f + 1] = 1;
    auto count_edge = [&](Index a, Index b) {
        const Index fa = free_index[a], fb = free_index[b];
        if (fa >= 0 && fb >= 0) ++begin[std::min(fa, fb) + 1];
    };
    for (const InteriorFacet& f : topology.interior_facets)
        count_edge(f.vertices[0], f.vertices[1]);
    for (const BoundaryFacet& f : topology.boundary_facets)
        count_edge(f.vertices[0], f.vertices[1]);
    for (Index f = 0; f < nf; ++f) begin[f + 1] += begin[f];
    Eigen::SparseMatrix<Complex> lower(nf, nf);
    lower.resizeNonZeros(begin[nf]);
    int* outer = lower.outerIndexPtr();
    int* rows = lower.innerIndexPtr();
    Complex* values = lower.valuePtr();
    std::copy(begin.begin(), begin.end(), outer);
    std::vector<int> cursor(begin.begin(), begin.end() - 1);
    for (Index f = 0; f < nf; ++f) {
        rows[cursor[f]] = static_cast<int>(f);
        values[cursor[f]++] = 0.0;
    }
    // L_ab = -w with w = (cot a_ab + cot b_ab) / 2, in both u and v.
    auto add_edge = [&](Index a, Index b, double w) {
        const Index fa = free_index[a], fb = free_index[b];
        if (fa >= 0) values[begin[fa]] += w;
        if (fb >= 0) values[begin[fb]] += w;
        if (fa >= 0 && fb >= 0) {
            const Index column = std::min(fa, fb);
            rows[cursor[column]] = static_cast<int>(std::max(fa, fb));
            values[cursor[column]++] = -w;
        } else if (fa >= 0) {
            rhs[fa] += w * Complex(x(b, 0), x(b, 1));
        } else if (fb >= 0) {
            rhs[fb] += w * Complex(x(a, 0), x(a, 1));
        }
    };
    for (const InteriorFacet& f : topology.interior_facets) {
        add_edge(f.vertices[0], f.vertices[1],
                 0.5 * (corner_cotangent(f.simplex[0], f.opposite[0]) +
                        corner_cotangent(f.simplex[1], f.opposite[1])));
    }
    for (const BoundaryFacet& f : topology.boundary_facets)
        add_edge(f.vertices[0], f.vertices[1], 0.5 * corner_cotangent(f.simplex, f.opposite));
    // Rows in order within each column (a few entries each), for the lookups below.
    std::vector<std::pair<int, Complex>> column_entries;
    for (Index f = 0; f < nf; ++f) {
        column_entries.clear();
        for (int p = begin[f]; p < begin[f + 1]; ++p)
            column_entries.emplace_back(rows[p], values[p]);
        std::sort(column_entries.begin(), column_entries.end(),
                  [](const auto& p, const auto& q) { return p.first < q.first; });
        for (std::size_t k = 0; k < column_entries.size(); ++k) {
            rows[begin[f] + k] = column_entries[k].first;
            values[begin[f] + k] = column_entries[k].second;
        }
    }
    // Edge i -> j of triangle s (opposite corner k): -sigma_s (u_i v_j - u_j v_i) = 2 h (v_j u_i
    // - v_i u_j) with h = -sigma_s / 2, i.e. C_ji += h (and C_ij = -C_ji). With a pin among i
    // and j, its terms go to the right-hand side instead.
    auto add_area_term = [&](Index s, int k) {
        const Index i = mesh.simplices(s, (k + 1) % 3), j = mesh.simplices(s, (k + 2) % 3);
        const double h = -0.5 * orientation(s);
        const Index fi = free_index[i], fj = free_index[j];
        if (fi >= 0 && fj >= 0) {
            const Index column = std::min(fi, fj), row = std::max(fi, fj);
            const int* entry = std::lower_bound(rows + begin[column], rows + begin[column + 1],
                                                static_cast<int>(row));
            values[entry - rows] += Complex(0.0, row == fj ? h : -h);  // C_row,column
            return;
        }
        if (fi >= 0) rhs[fi] += h * Complex(-x(j, 1), x(j, 0));  // -h v_j in r, h u_j in s
        if (fj >= 0) rhs[fj] += h * Complex(x(i, 1), -x(i, 0));  // h v_i in r, -h u_i in s
    };
    for (const BoundaryFacet& f : topology.boundary_facets) add_area_term(f.simplex, f.opposite);
    if (planar) {
        for (const InteriorFacet& f : topology.interior_facets) {
            if (orientation(f.simplex[0]) == orientation(f.simplex[1])) continue;
            add_area_term(f.simplex[0], f.opposite[0]);
            add_area_term(f.simplex[1], f.opposite[1]);
        }
    }
    const std::optional<Eigen::VectorXcd> solution = solve_hermitian_positive_definite(lower, rhs);
    if (!solution)
        throw InvalidArgumentError("lscm: the system is singular (is the mesh connected?)");
    for (Index v = 0; v < nv; ++v) {
        if (free_index[v] >= 0)
            x.row(v) << (*solution)[free_index[v]].real(), (*solution)[free_index[v]].imag();
    }
    return x;
}

}  // namespace sa
