#include "geometry/generated_problems.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <random>
#include <string>

#include "geometry/map_quality.h"
#include "geometry/mesh_topology.h"
#include "geometry/rest_frames.h"
#include "optim/errors.h"

namespace sa {

namespace {

struct Axes {
    int along = 0;   ///< the longest side
    int across = 1;  ///< the shortest side (bend plane, flatten direction)
    int other = 2;   ///< the third one (3D)
    Eigen::RowVectorXd low, high, center;
};

Axes axes_of(const Eigen::MatrixXd& rest) {
    Axes a;
    a.low = rest.colwise().minCoeff();
    a.high = rest.colwise().maxCoeff();
    a.center = 0.5 * (a.low + a.high);
    const Eigen::RowVectorXd size = a.high - a.low;
    const int d = static_cast<int>(rest.cols());
    size.maxCoeff(&a.along);
    a.across = a.along == 0 ? 1 : 0;
    for (int c = 0; c < d; ++c) {
        if (c != a.along && size[c] < size[a.across]) a.across = c;
    }
    a.other = 3 - a.along - a.across;
    return a;
}

/// Throws unless `solution` keeps every simplex of `rest` positively oriented and not flat.
void check_valid(const SimplicialMesh& rest, const Eigen::MatrixXd& solution, const char* what) {
    auto check = [&]<int D>() {
        const RestFrames<D> frames = rest_frames<D>(rest);
        const MapQuality q = map_quality<D>(linear_parts<D>(rest, frames, solution), frames.volume);
        if (q.inverted + q.degenerate > 0) {
            throw InvalidArgumentError(std::string(what) +
                                       ": the deformation inverts or flattens " +
                                       std::to_string(q.inverted + q.degenerate) +
                                       " simplices of the rest mesh; use a smaller amount");
        }
    };
    if (rest.simplex_dimension() == 3) {
        check.template operator()<3>();
    } else {
        check.template operator()<2>();
    }
}

}  // namespace

Eigen::MatrixXd deform(const Eigen::MatrixXd& rest, GeneratedDeformation deformation, double amount,
                       double flatten) {
    const Axes ax = axes_of(rest);
    const double length = ax.high[ax.along] - ax.low[ax.along];
    Eigen::MatrixXd out = rest;
    for (Index v = 0; v < rest.rows(); ++v) {
        const double t = (rest(v, ax.along) - ax.low[ax.along]) / length;  // 0 .. 1
        if (deformation == GeneratedDeformation::kTwist) {
            if (rest.cols() != 3)
                throw InvalidArgumentError("deform: a twist needs a mesh in space (3 columns)");
            const double angle = amount * t, c = std::cos(angle), s = std::sin(angle);
            const double u = rest(v, ax.across) - ax.center[ax.across];
            const double w = rest(v, ax.other) - ax.center[ax.other];
            out(v, ax.across) = ax.center[ax.across] + c * u - s * w;
            out(v, ax.other) = ax.center[ax.other] + s * u + c * w;
        } else if (amount != 0.0) {
            // The axis onto an arc of radius R = length / amount centred below the bar.
            const double radius = length / amount;
            const double phi = amount * (t - 0.5);
            const double r = radius + (rest(v, ax.across) - ax.center[ax.across]);
            out(v, ax.along) = ax.center[ax.along] + r * std::sin(phi);
            out(v, ax.across) = ax.center[ax.across] + r * std::cos(phi) - radius;
        }
    }
    if (flatten != 1.0) {
        const double middle = 0.5 * (out.col(ax.across).minCoeff() + out.col(ax.across).maxCoeff());
        out.col(ax.across) = (out.col(ax.across).array() - middle) * flatten + middle;
    }
    return out;
}

GeneratedProblem fixed_boundary_problem(const SimplicialMesh& rest,
                                        GeneratedDeformation deformation, double amount,
                                        double noise, std::uint64_t seed, double flatten) {
    GeneratedProblem p;
    p.rest = rest;
    p.solution = deform(rest.vertices, deformation, amount, flatten);
    check_valid(rest, p.solution, "fixed_boundary_problem");
    const MeshTopology topology = mesh_topology(rest, "generated problem");
    const Index nv = rest.num_vertices();
    std::vector<Index> free_index(nv, -1);
    Index nf = 0;
    for (Index v = 0; v < nv; ++v) {
        if (!topology.used_vertex[v]) continue;
        if (topology.boundary_vertex[v]) {
            p.handles.push_back(v);
        } else {
            free_index[v] = nf++;
        }
    }
    if (nf == 0)
        throw InvalidArgumentError("fixed_boundary_problem: the mesh has no interior vertex");

    // Tutte: every interior vertex at the mean of its neighbours, the boundary fixed.
    const Index d = rest.vertices.cols();
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nf, d);
    double edge_length = 0.0;
    for (const auto& e : topology.edges) {
        edge_length += (rest.vertices.row(e[0]) - rest.vertices.row(e[1])).norm();
        for (int k = 0; k < 2; ++k) {
            const Index a = e[k], b = e[1 - k];
            if (free_index[a] < 0) continue;
            entries.emplace_back(free_index[a], free_index[a], 1.0);
            if (free_index[b] >= 0) {
                entries.emplace_back(free_index[a], free_index[b], -1.0);
            } else {
                rhs.row(free_index[a]) += p.solution.row(b);
            }
        }
    }
    edge_length /= double(topology.edges.size());
    Eigen::SparseMatrix<double> L(nf, nf);
    L.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(L);
    const Eigen::MatrixXd interior = solver.solve(rhs);

    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> uniform;
    p.initial = p.solution;
    for (Index v = 0; v < nv; ++v) {
        if (free_index[v] < 0) continue;
        Eigen::RowVectorXd direction(d);
        for (Index c = 0; c < d; ++c) direction[c] = normal(rng);
        const double radius = noise * edge_length * std::pow(uniform(rng), 1.0 / double(d));
        p.initial.row(v) = interior.row(free_index[v]) + radius * direction.normalized();
    }
    return p;
}

GeneratedProblem handle_slab_problem(const SimplicialMesh& rest, GeneratedDeformation deformation,
                                     double amount, double slab) {
    GeneratedProblem p;
    p.rest = rest;
    p.solution = deform(rest.vertices, deformation, amount);
    check_valid(rest, p.solution, "handle_slab_problem");
    const Axes ax = axes_of(rest.vertices);
    const double length = ax.high[ax.along] - ax.low[ax.along];
    p.initial = rest.vertices;
    for (Index v = 0; v < rest.num_vertices(); ++v) {
        const double t = (rest.vertices(v, ax.along) - ax.low[ax.along]) / length;
        if (t <= slab || t >= 1.0 - slab) {
            p.handles.push_back(v);
            p.initial.row(v) = p.solution.row(v);
        }
    }
    return p;
}

}  // namespace sa
