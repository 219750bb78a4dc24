#include "geometry/maps/handle_rotation_start.h"

#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "geometry/detail/union_find.h"
#include "geometry/maps/rotation_fit.h"

namespace sa {

namespace {

/// A rotation as a unit vector: (cos, sin) in 2D, the quaternion (w, x, y, z) in 3D.
template <int D>
using Rep = Eigen::Matrix<double, D == 2 ? 2 : 4, 1>;

template <int D>
Rep<D> rep_of(const Mat<D>& R) {
    if constexpr (D == 2) {
        return Rep<D>(R(0, 0), R(1, 0)).normalized();
    } else {
        const Eigen::Quaterniond q(R);
        return Rep<D>(q.w(), q.x(), q.y(), q.z()).normalized();
    }
}

template <int D>
Mat<D> rotation_of(const Rep<D>& r) {
    const double norm = r.norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) return Mat<D>::Identity();
    const Rep<D> u = r / norm;
    if constexpr (D == 2) {
        Mat<2> R;
        R << u[0], -u[1], u[1], u[0];
        return R;
    } else {
        return Eigen::Quaterniond(u[0], u[1], u[2], u[3]).toRotationMatrix();
    }
}

/// A group of handles: its best rigid rotation, and whether its rest positions determine it.
template <int D>
struct Group {
    std::vector<Index> vertices;
    Mat<D> rotation = Mat<D>::Identity();
    bool determined = false;
};

template <int D>
void fit_group(const SimplicialMesh& mesh, const Eigen::MatrixXd& start, Group<D>& g) {
    Vec<D> rest_mean = Vec<D>::Zero(), target_mean = Vec<D>::Zero();
    for (Index v : g.vertices) {
        rest_mean += mesh.vertices.row(v).head<D>().transpose();
        target_mean += start.row(v).head<D>().transpose();
    }
    rest_mean /= double(g.vertices.size());
    target_mean /= double(g.vertices.size());
    Mat<D> spread = Mat<D>::Zero(), cross = Mat<D>::Zero();
    for (Index v : g.vertices) {
        const Vec<D> p = mesh.vertices.row(v).head<D>().transpose() - rest_mean;
        const Vec<D> t = start.row(v).head<D>().transpose() - target_mean;
        spread += p * p.transpose();
        cross += t * p.transpose();
    }
    g.rotation = fit_rotation<D>(cross);
    // Determined when the rest positions span at least D - 1 dimensions (eigenvalues increase).
    const Vec<D> extent =
        Eigen::SelfAdjointEigenSolver<Mat<D>>(spread, Eigen::EigenvaluesOnly).eigenvalues();
    g.determined = extent[D - 1] > 0.0 && (D == 2 || extent[1] > 1e-6 * extent[D - 1]);
}

}  // namespace

template <int D>
HandleRotationStart handle_rotation_start(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                                          const VertexRecovery<D>& recovery,
                                          const Eigen::MatrixXd& start) {
    const Index nv = mesh.num_vertices(), ns = mesh.num_simplices();
    const std::vector<unsigned char>& fixed = recovery.fixed();
    UnionFind handles(nv), parts(nv);
    for (Index s = 0; s < ns; ++s) {
        for (int a = 0; a <= D; ++a) {
            for (int b = a + 1; b <= D; ++b) {
                const Index va = mesh.simplices(s, a), vb = mesh.simplices(s, b);
                parts.join(va, vb);
                if (fixed[va] && fixed[vb]) handles.join(va, vb);
            }
        }
    }
    // The groups, in the order of their first vertex.
    std::vector<Group<D>> groups;
    std::vector<Index> group_of_root(nv, -1);
    for (Index v = 0; v < nv; ++v) {
        if (!fixed[v]) continue;
        Index& g = group_of_root[handles.find(v)];
        if (g < 0) {
            g = static_cast<Index>(groups.size());
            groups.emplace_back();
        }
        groups[g].vertices.push_back(v);
    }
    HandleRotationStart result;
    result.groups = static_cast<int>(groups.size());
    for (Group<D>& g : groups) {
        fit_group<D>(mesh, start, g);
        result.rotation_groups += g.determined;
    }
    // Connected parts without a determined group: one group of all their handles.
    std::vector<unsigned char> anchored(nv, 0);
    for (const Group<D>& g : groups) {
        if (g.determined) anchored[parts.find(g.vertices.front())] = 1;
    }
    std::vector<Group<D>> sources;
    std::vector<Index> part_group(nv, -1);
    for (const Group<D>& g : groups) {
        if (g.determined) {
            sources.push_back(g);
            continue;
        }
        const Index part = parts.find(g.vertices.front());
        if (anchored[part]) continue;
        if (part_group[part] < 0) {
            part_group[part] = static_cast<Index>(sources.size());
            sources.emplace_back();
        }
        auto& vertices = sources[part_group[part]].vertices;
        vertices.insert(vertices.end(), g.vertices.begin(), g.vertices.end());
    }
    for (Index part = 0; part < nv; ++part) {
        if (part_group[part] >= 0) fit_group<D>(mesh, start, sources[part_group[part]]);
    }

    std::vector<Mat<D>> rotations(ns, Mat<D>::Identity());
    if (sources.size() == 1) {
        std::fill(rotations.begin(), rotations.end(), sources.front().rotation);
    } else if (sources.size() > 1) {
        // Signs towards the largest group's, then the harmonic field with the groups fixed.
        std::size_t largest = 0;
        for (std::size_t k = 1; k < sources.size(); ++k) {
            if (sources[k].vertices.size() > sources[largest].vertices.size()) largest = k;
        }
        const Rep<D> reference = rep_of<D>(sources[largest].rotation);
        constexpr int K = Rep<D>::RowsAtCompileTime;
        Eigen::MatrixXd values = Eigen::MatrixXd::Zero(nv, K);
        std::vector<unsigned char> source_vertex(nv, 0);
        for (const Group<D>& g : sources) {
            Rep<D> r = rep_of<D>(g.rotation);
            if (r.dot(reference) < 0.0) r = -r;
            for (Index v : g.vertices) {
                values.row(v) = r.transpose();
                source_vertex[v] = 1;
            }
        }
        const VertexRecovery<D> field(mesh, frames, std::move(source_vertex));
        const std::vector<Mat<D>> zero(ns, Mat<D>::Zero());
        Eigen::MatrixXd harmonic(nv, K);
        for (int c = 0; c < K; c += D) {  // D components per solve
            const int n = std::min(D, K - c);
            Eigen::MatrixXd block = Eigen::MatrixXd::Zero(nv, D);
            block.leftCols(n) = values.middleCols(c, n);
            harmonic.middleCols(c, n) = field.recover(zero, block).leftCols(n);
        }
        tbb::parallel_for(Index(0), ns, [&](Index s) {
            Rep<D> sum = Rep<D>::Zero();
            for (int k = 0; k <= D; ++k) sum += harmonic.row(mesh.simplices(s, k)).transpose();
            rotations[s] = rotation_of<D>(sum);
        });
    }
    result.positions = recovery.recover(rotations, start);
    return result;
}

template HandleRotationStart handle_rotation_start<2>(const SimplicialMesh&, const RestFrames<2>&,
                                                      const VertexRecovery<2>&,
                                                      const Eigen::MatrixXd&);
template HandleRotationStart handle_rotation_start<3>(const SimplicialMesh&, const RestFrames<3>&,
                                                      const VertexRecovery<3>&,
                                                      const Eigen::MatrixXd&);

}  // namespace sa
