#include "frontends/seamless/cross_field.h"

#include <Eigen/Geometry>
#include <Eigen/Sparse>
#include <cmath>
#include <complex>
#include <random>
#include <unordered_map>

#include "optim/errors.h"
#include "optim/linear_solver.h"

namespace sa {

namespace {

using Complex = std::complex<double>;

/// Each face's orthonormal tangent frame (e1 along its first edge, e2 = n x e1) and area.
struct FaceFrames {
    std::vector<Eigen::Vector3d> e1, e2;
    std::vector<double> area;

    explicit FaceFrames(const SimplicialMesh& mesh) {
        const Index nf = mesh.num_simplices();
        e1.resize(nf);
        e2.resize(nf);
        area.resize(nf);
        for (Index f = 0; f < nf; ++f) {
            const Eigen::Vector3d p0 = mesh.point(mesh.simplices(f, 0));
            const Eigen::Vector3d a = mesh.point(mesh.simplices(f, 1)) - p0,
                                  b = mesh.point(mesh.simplices(f, 2)) - p0;
            const Eigen::Vector3d n = a.cross(b);
            if (!(n.norm() > 0.0))
                throw InputError("cross field: face " + std::to_string(f) + " is degenerate");
            area[f] = 0.5 * n.norm();
            e1[f] = a.normalized();
            e2[f] = n.normalized().cross(e1[f]);
        }
    }
    /// The tangent part of w in face f's frame, as a complex number.
    Complex coordinates(Index f, const Eigen::Vector3d& w) const {
        return {w.dot(e1[f]), w.dot(e2[f])};
    }
    /// The unit complex coordinate of the edge vector w in face f.
    Complex direction(Index f, const Eigen::Vector3d& w) const {
        const Complex c = coordinates(f, w);
        return c / std::abs(c);
    }
};

/// r_fg across the interior facet: u_g = r_fg u_f transports a direction from f to g.
Complex transport(const SimplicialMesh& mesh, const FaceFrames& frames,
                  const InteriorFacet& facet) {
    const Eigen::Vector3d e = mesh.point(facet.vertices[1]) - mesh.point(facet.vertices[0]);
    return std::conj(frames.direction(facet.simplex[0], e)) * frames.direction(facet.simplex[1], e);
}

/// Adds the complex entry a at (r, c) of an n x n Hermitian matrix in its real 2n x 2n form.
void add_complex(std::vector<Eigen::Triplet<double>>& t, Index n, Index r, Index c, Complex a) {
    t.emplace_back(r, c, a.real());
    t.emplace_back(r, n + c, -a.imag());
    t.emplace_back(n + r, c, a.imag());
    t.emplace_back(n + r, n + c, a.real());
}

Eigen::SparseMatrix<double> lower_of(Index size,
                                     const std::vector<Eigen::Triplet<double>>& entries) {
    Eigen::SparseMatrix<double> full(size, size);
    full.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseMatrix<double> lower = full.triangularView<Eigen::Lower>();
    return lower;
}

double wrap_quarter(double angle) {  // into (-pi/4, pi/4]
    const double quarter = 0.5 * M_PI;
    return angle - quarter * std::ceil(angle / quarter - 0.5);
}

}  // namespace

Eigen::MatrixXd smoothest_cross_field(const SimplicialMesh& mesh, const MeshTopology& topology,
                                      const std::vector<CrossFieldConstraint>& constraints) {
    if (mesh.simplex_dimension() != 2)
        throw InvalidArgumentError("smoothest_cross_field: needs a triangle mesh");
    const FaceFrames frames(mesh);
    const Index nf = mesh.num_simplices();

    // Boundary faces are fixed to their boundary edge's direction (z = c^4).
    std::vector<Index> unknown(nf, 0);
    std::vector<Complex> fixed(nf, Complex(0.0, 0.0));
    std::vector<unsigned char> is_fixed(nf, 0);
    for (const BoundaryFacet& b : topology.boundary_facets) {
        if (is_fixed[b.simplex]) continue;
        const Eigen::Vector3d e = mesh.point(b.vertices[1]) - mesh.point(b.vertices[0]);
        fixed[b.simplex] = std::pow(frames.direction(b.simplex, e), 4);
        is_fixed[b.simplex] = 1;
    }
    for (const CrossFieldConstraint& c : constraints) {
        if (c.face < 0 || c.face >= nf) {
            throw InputError("cross field: constrained face " + std::to_string(c.face) +
                             " is out of range (the mesh has " + std::to_string(nf) + " faces)");
        }
        const Complex d = frames.coordinates(c.face, c.direction);
        if (!(std::abs(d) > 1e-6 * c.direction.norm()) || !std::isfinite(std::abs(d))) {
            throw InputError("cross field: the direction given for face " + std::to_string(c.face) +
                             " is zero or normal to the face");
        }
        fixed[c.face] = std::pow(d / std::abs(d), 4);
        is_fixed[c.face] = 1;
    }
    Index n = 0;
    for (Index f = 0; f < nf; ++f) unknown[f] = is_fixed[f] ? -1 : n++;

    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * n);
    for (const InteriorFacet& facet : topology.interior_facets) {
        // |z_g - R z_f|^2 with R = r_fg^4: A_ff += 1, A_gg += 1, A_gf -= R, A_fg -= conj(R).
        const Complex R = std::pow(transport(mesh, frames, facet), 4);
        const Index f = facet.simplex[0], g = facet.simplex[1];
        const Index uf = unknown[f], ug = unknown[g];
        if (uf >= 0) add_complex(entries, n, uf, uf, 1.0);
        if (ug >= 0) add_complex(entries, n, ug, ug, 1.0);
        auto couple = [&](Index row, Index other_face, Complex a) {  // a z_other on row `row`
            if (unknown[other_face] >= 0) {
                add_complex(entries, n, row, unknown[other_face], a);
            } else {
                const Complex moved = -a * fixed[other_face];
                rhs[row] += moved.real();
                rhs[n + row] += moved.imag();
            }
        };
        if (ug >= 0) couple(ug, f, -R);
        if (uf >= 0) couple(uf, g, -std::conj(R));
    }

    Eigen::VectorXd z;
    if (n > 0 && n < nf) {
        LinearSolver solver(LinearSolverType::kCholmodSupernodal, FillOrdering::kAmd);
        const Eigen::SparseMatrix<double> lower = lower_of(2 * n, entries);
        solver.analyze(lower);
        if (solver.factorize(lower) != FactorizationStatus::kSuccess) {
            throw InputError(
                "smoothest_cross_field: singular system (a part of the mesh touches no boundary "
                "and no constrained face?)");
        }
        z = solver.solve(rhs);
    } else if (n == nf) {
        // Closed: the smallest eigenvector of A z = lambda M z, by inverse iteration on A + eps M.
        double trace = 0.0, total_area = 0.0;
        for (Index f = 0; f < nf; ++f) total_area += frames.area[f];
        for (const auto& t : entries) trace += t.row() == t.col() ? t.value() : 0.0;
        const double eps = 1e-8 * trace / total_area;
        Eigen::VectorXd mass(2 * n);
        for (Index f = 0; f < nf; ++f) mass[unknown[f]] = mass[n + unknown[f]] = frames.area[f];
        for (Index i = 0; i < 2 * n; ++i) entries.emplace_back(i, i, eps * mass[i]);
        LinearSolver solver(LinearSolverType::kCholmodSupernodal);
        const Eigen::SparseMatrix<double> lower = lower_of(2 * n, entries);
        solver.analyze(lower);
        if (solver.factorize(lower) != FactorizationStatus::kSuccess) {
            throw InputError(
                "smoothest_cross_field: the connection Laplacian could not be factored");
        }
        std::mt19937 rng(1);
        std::normal_distribution<double> normal;
        z.resize(2 * n);
        for (Index i = 0; i < 2 * n; ++i) z[i] = normal(rng);
        for (int iteration = 0; iteration < 50; ++iteration) {
            z = solver.solve(mass.cwiseProduct(z));
            z /= std::sqrt(z.dot(mass.cwiseProduct(z)));
        }
    }
    Eigen::MatrixXd directions(nf, 3);
    for (Index f = 0; f < nf; ++f) {
        const Complex zf = unknown[f] >= 0 ? Complex(z[unknown[f]], z[n + unknown[f]]) : fixed[f];
        const double angle = std::arg(zf) / 4.0;
        directions.row(f) =
            (std::cos(angle) * frames.e1[f] + std::sin(angle) * frames.e2[f]).transpose();
    }
    return directions;
}

std::vector<Singularity> cross_field_singularities(const SimplicialMesh& mesh,
                                                   const MeshTopology& topology,
                                                   const Eigen::MatrixXd& directions) {
    const Index nf = mesh.num_simplices(), nv = mesh.num_vertices();
    if (directions.rows() != nf || directions.cols() != 3) {
        throw InputError("cross field: " + std::to_string(directions.rows()) + " x " +
                         std::to_string(directions.cols()) + " directions for " +
                         std::to_string(nf) + " faces (expected #F x 3)");
    }
    const FaceFrames frames(mesh);
    std::vector<double> angle(nf);
    for (Index f = 0; f < nf; ++f) {
        const Eigen::Vector3d d = directions.row(f).transpose();
        const Complex c = frames.coordinates(f, d);
        if (!(std::abs(c) > 0.5 * d.norm()) || !(d.norm() > 0.0)) {
            throw InputError("cross field: the direction of face " + std::to_string(f) +
                             " vanishes or is not tangent to the face");
        }
        angle[f] = std::arg(c);
    }
    // face_of[a * nv + b] = the face with the directed edge a -> b.
    std::unordered_map<long long, Index> face_of;
    face_of.reserve(3 * nf);
    for (Index f = 0; f < nf; ++f) {
        for (int k = 0; k < 3; ++k) {
            face_of[(long long)mesh.simplices(f, k) * nv + mesh.simplices(f, (k + 1) % 3)] = f;
        }
    }
    std::vector<Singularity> singularities;
    for (Index v = 0; v < nv; ++v) {
        if (!topology.used_vertex[v] || topology.boundary_vertex[v]) continue;
        const Index start = topology.simplices_of_vertex[topology.vertex_begin[v]];
        double total = 2.0 * M_PI;  // the angle defect plus the field's turning
        Index f = start;
        do {
            int k = 0;
            while (mesh.simplices(f, k) != v) ++k;
            const Index a = mesh.simplices(f, (k + 1) % 3), b = mesh.simplices(f, (k + 2) % 3);
            const Eigen::Vector3d pv = mesh.point(v), ea = mesh.point(a) - pv,
                                  eb = mesh.point(b) - pv;
            total -= std::atan2(ea.cross(eb).norm(), ea.dot(eb));
            // The next face counter-clockwise around v holds the directed edge v -> b.
            const auto next = face_of.find((long long)v * nv + b);
            if (next == face_of.end())
                throw InputError("cross field: the mesh is not oriented around vertex " +
                                 std::to_string(v));
            const Index g = next->second;
            const Complex r = std::conj(frames.direction(f, eb)) * frames.direction(g, eb);
            total += wrap_quarter(angle[g] - angle[f] - std::arg(r));
            f = g;
        } while (f != start);
        const double index = std::round(4.0 * total / (2.0 * M_PI)) / 4.0;
        if (index != 0.0) singularities.push_back({v, index});
    }
    return singularities;
}

}  // namespace sa
