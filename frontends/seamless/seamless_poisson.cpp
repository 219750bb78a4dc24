#include "frontends/seamless/seamless_poisson.h"

#include <Eigen/Sparse>
#include <cmath>

#include "geometry/mesh/rest_frames.h"
#include "optim/errors.h"
#include "optim/linear_solver.h"

namespace sa {

namespace {

/// Rotation by -k quarter turns.
Mat<2> seam_rotation(int k) {
    const double a = -0.5 * M_PI * k;
    Mat<2> r;
    r << std::round(std::cos(a)), -std::round(std::sin(a)), std::round(std::sin(a)),
        std::round(std::cos(a));
    return r;
}

/// The corner of face f holding a copy of original vertex v.
Index copy_in(const CutMesh& cut, Index f, Index v) {
    for (int k = 0; k < 3; ++k) {
        const Index c = cut.mesh.simplices(f, k);
        if (cut.original_vertex[c] == v) return c;
    }
    throw InvalidArgumentError("seamless_poisson: vertex " + std::to_string(v) +
                               " is not in face " + std::to_string(f));
}

}  // namespace

SeamlessMap seamless_poisson(const SimplicialMesh& mesh, const MeshTopology& topology,
                             const std::vector<unsigned char>& cut,
                             const std::vector<int>& matching,
                             const std::vector<Mat<2>>& jacobians) {
    const Index nf = mesh.num_simplices();
    if (Index(jacobians.size()) != nf || matching.size() != topology.interior_facets.size() ||
        cut.size() != topology.interior_facets.size()) {
        throw InvalidArgumentError(
            "seamless_poisson: expected one Jacobian per face and one matching and cut flag per "
            "interior edge");
    }
    SeamlessMap out;
    out.cut = cut_along(mesh, topology, cut);
    const RestFrames<2> frames = rest_frames<2>(mesh);
    const Index nc = out.cut.mesh.num_vertices();

    // Combing: t_g = t_f + k across every uncut edge (breadth-first from one face per part), so
    // that the turned targets Rot(t_f) J_f match across it; a seam's matching becomes
    // k + t_f - t_g.
    out.chart_turns.assign(nf, -1);
    std::vector<std::vector<std::pair<Index, int>>> uncut(nf);  // (neighbour, turns to it)
    for (std::size_t i = 0; i < cut.size(); ++i) {
        if (cut[i]) continue;
        const auto& s = topology.interior_facets[i].simplex;
        uncut[s[0]].emplace_back(s[1], matching[i]);
        uncut[s[1]].emplace_back(s[0], -matching[i]);
    }
    for (Index root = 0; root < nf; ++root) {
        if (out.chart_turns[root] >= 0) continue;
        out.chart_turns[root] = 0;
        std::vector<Index> queue{root};
        for (std::size_t q = 0; q < queue.size(); ++q) {
            const Index f = queue[q];
            for (const auto& [g, k] : uncut[f]) {
                if (out.chart_turns[g] >= 0) continue;
                out.chart_turns[g] = ((out.chart_turns[f] + k) % 4 + 4) % 4;
                queue.push_back(g);
            }
        }
    }
    std::vector<int> seam_turns(cut.size());
    for (std::size_t i = 0; i < cut.size(); ++i) {
        const auto& s = topology.interior_facets[i].simplex;
        seam_turns[i] = ((matching[i] + out.chart_turns[s[0]] - out.chart_turns[s[1]]) % 4 + 4) % 4;
        if (!cut[i] && seam_turns[i] != 0) {
            throw InvalidArgumentError(
                "seamless_poisson: the field turns around an uncut vertex (the cut misses a "
                "singularity near faces " +
                std::to_string(s[0]) + " and " + std::to_string(s[1]) + ")");
        }
    }

    // Gauge: the first vertex of each connected part of the cut mesh is fixed at the origin.
    const MeshTopology cut_topology = mesh_topology(out.cut.mesh, "cut mesh");
    Index parts = 0;
    const std::vector<Index> part = cut_topology.simplex_components(&parts);
    std::vector<unsigned char> pinned(nc, 0), part_pinned(parts, 0);
    for (Index f = 0; f < nf; ++f) {
        if (!part_pinned[part[f]]) {
            part_pinned[part[f]] = 1;
            pinned[out.cut.mesh.simplices(f, 0)] = 1;
        }
    }
    std::vector<Index> unknown(nc, -1);
    Index n = 0;
    for (Index c = 0; c < nc; ++c) {
        if (!pinned[c]) unknown[c] = n++;
    }

    // Least squares rows: sum over (weight, [(vertex, component, coefficient)...], target).
    std::vector<Eigen::Triplet<double>> rows;
    std::vector<double> rhs;
    auto add_row = [&](double weight, std::initializer_list<std::tuple<Index, int, double>> terms,
                       double target) {
        const Index r = Index(rhs.size());
        for (const auto& [c, component, coefficient] : terms) {
            if (unknown[c] >= 0)
                rows.emplace_back(r, 2 * unknown[c] + component, weight * coefficient);
        }
        rhs.push_back(weight * target);
    };
    double edge_length = 0.0, area = 0.0;
    for (Index f = 0; f < nf; ++f) {
        const Mat<2>& E = frames.edge_inverse[f];
        const Mat<2> target = seam_rotation(-out.chart_turns[f]) * jacobians[f];
        const double w = std::sqrt(frames.volume[f]);
        area += frames.volume[f];
        const Index p0 = out.cut.mesh.simplices(f, 0), p1 = out.cut.mesh.simplices(f, 1),
                    p2 = out.cut.mesh.simplices(f, 2);
        edge_length += (frames.corner(f, 1) - frames.corner(f, 0)).norm();
        // J(r, c) = (p1_r - p0_r) E(0, c) + (p2_r - p0_r) E(1, c).
        for (int r = 0; r < 2; ++r) {
            for (int c = 0; c < 2; ++c) {
                add_row(w, {{p1, r, E(0, c)}, {p2, r, E(1, c)}, {p0, r, -E(0, c) - E(1, c)}},
                        target(r, c));
            }
        }
    }
    edge_length /= double(nf);
    const double seam_weight = 1e4 * std::sqrt(area / double(nf)) / edge_length;
    struct Seam {
        Index al, bl, ar, br;
        Mat<2> R;
    };
    std::vector<Seam> seams;
    for (std::size_t i = 0; i < topology.interior_facets.size(); ++i) {
        if (!cut[i]) continue;
        const InteriorFacet& facet = topology.interior_facets[i];
        const Index l = facet.simplex[0], r = facet.simplex[1], a = facet.vertices[0],
                    b = facet.vertices[1];
        const Seam s{copy_in(out.cut, l, a), copy_in(out.cut, l, b), copy_in(out.cut, r, a),
                     copy_in(out.cut, r, b), seam_rotation(seam_turns[i])};
        seams.push_back(s);
        for (int row = 0; row < 2;
             ++row) {  // (p_br - p_ar)_row - sum_c R(row, c) (p_bl - p_al)_c = 0
            add_row(seam_weight,
                    {{s.br, row, 1.0},
                     {s.ar, row, -1.0},
                     {s.bl, 0, -s.R(row, 0)},
                     {s.al, 0, s.R(row, 0)},
                     {s.bl, 1, -s.R(row, 1)},
                     {s.al, 1, s.R(row, 1)}},
                    0.0);
        }
    }
    Eigen::SparseMatrix<double> M(Index(rhs.size()), 2 * n);
    M.setFromTriplets(rows.begin(), rows.end());  // repeated (row, column) entries are summed
    const Eigen::SparseMatrix<double> normal = M.transpose() * M;
    const Eigen::SparseMatrix<double> lower = normal.triangularView<Eigen::Lower>();
    LinearSolver solver(LinearSolverType::kCholmodSupernodal, FillOrdering::kAmd);
    solver.analyze(lower);
    if (solver.factorize(lower) != FactorizationStatus::kSuccess) {
        throw InputError("seamless_poisson: the system is singular (a degenerate face?)");
    }
    const Eigen::VectorXd x = solver.solve(
        M.transpose() * Eigen::Map<const Eigen::VectorXd>(rhs.data(), Index(rhs.size())));
    out.uv = Eigen::MatrixXd::Zero(nc, 2);
    for (Index c = 0; c < nc; ++c) {
        if (unknown[c] >= 0) out.uv.row(c) << x[2 * unknown[c]], x[2 * unknown[c] + 1];
    }
    double uv_edge_length = 0.0;  // the mean over the faces' first edges, as edge_length
    for (Index f = 0; f < nf; ++f) {
        uv_edge_length +=
            (out.uv.row(out.cut.mesh.simplices(f, 1)) - out.uv.row(out.cut.mesh.simplices(f, 0)))
                .norm();
    }
    uv_edge_length /= double(nf);
    for (const Seam& s : seams) {
        const Vec<2> df = (out.uv.row(s.bl) - out.uv.row(s.al)).transpose();
        const Vec<2> dg = (out.uv.row(s.br) - out.uv.row(s.ar)).transpose();
        out.max_seam_mismatch =
            std::max(out.max_seam_mismatch, (dg - s.R * df).norm() / uv_edge_length);
    }
    return out;
}

}  // namespace sa
