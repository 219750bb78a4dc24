#include "geometry/quality/map_quality.h"

#include <tbb/parallel_for.h>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>

namespace sa {

namespace {

/// map_quality()'s rule for a degenerate simplex, given the largest |det A_j| vol_j.
bool degenerate(double det, double volume, double largest) {
    return !std::isfinite(det) || std::abs(det) * volume <= 1e-14 * largest;
}

}  // namespace

template <int D>
Index count_degenerate(const std::vector<Mat<D>>& A, const std::vector<double>& rest_volume) {
    const Index n = static_cast<Index>(A.size());
    std::vector<double> det(n);
    tbb::parallel_for(Index(0), n, [&](Index i) { det[i] = A[i].determinant(); });
    double largest = 0.0;
    for (Index i = 0; i < n; ++i)
        if (std::isfinite(det[i])) largest = std::max(largest, std::abs(det[i]) * rest_volume[i]);
    Index count = 0;
    for (Index i = 0; i < n; ++i) count += degenerate(det[i], rest_volume[i], largest);
    return count;
}

template <int D>
MapQuality map_quality(const std::vector<Mat<D>>& A, const std::vector<double>& rest_volume) {
    MapQuality q;
    const Index n = static_cast<Index>(A.size());
    q.simplices = n;
    q.per_simplex.resize(n);
    tbb::parallel_for(Index(0), n, [&](Index i) {
        SimplexQuality& s = q.per_simplex[i];
        s.det = A[i].determinant();
        if (!std::isfinite(s.det)) {
            s.degenerate = true;
            return;
        }
        s.inverted = s.det < 0.0;
        const Vec<D> sigma = Eigen::JacobiSVD<Mat<D>>(A[i]).singularValues();
        if (s.inverted || !(sigma[D - 1] > 0.0)) return;
        s.conformal = sigma[0] / sigma[D - 1];
        s.isometric = std::max(sigma[0], 1.0 / sigma[D - 1]);
        s.volumetric = std::max(s.det, 1.0 / s.det);
    });
    double largest = 0.0;
    for (Index i = 0; i < n; ++i) {
        if (std::isfinite(q.per_simplex[i].det))
            largest = std::max(largest, std::abs(q.per_simplex[i].det) * rest_volume[i]);
    }
    double weight = 0.0;
    for (Index i = 0; i < n; ++i) {
        SimplexQuality& s = q.per_simplex[i];
        if (!s.degenerate && degenerate(s.det, rest_volume[i], largest)) s.degenerate = true;
        q.inverted += s.inverted;
        q.degenerate += s.degenerate;
        if (s.inverted || s.degenerate) continue;
        const double w = rest_volume[i];
        weight += w;
        for (auto [stat, value] :
             {std::pair{&q.conformal, s.conformal}, std::pair{&q.isometric, s.isometric},
              std::pair{&q.volumetric, s.volumetric}}) {
            stat->max = std::max(stat->max, value);
            stat->mean += w * value;
        }
    }
    for (QualityStat* stat : {&q.conformal, &q.isometric, &q.volumetric}) {
        stat->mean = weight > 0.0 ? stat->mean / weight : kInfinity;
        if (weight == 0.0) stat->max = kInfinity;
    }
    return q;
}

template <int D>
std::vector<Mat<D>> linear_parts(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                                 const Eigen::MatrixXd& positions) {
    std::vector<Mat<D>> A(mesh.num_simplices());
    tbb::parallel_for(Index(0), mesh.num_simplices(), [&](Index s) {
        Eigen::Matrix<double, D, D + 1> mapped;
        for (int k = 0; k <= D; ++k)
            mapped.col(k) = positions.row(mesh.simplices(s, k)).transpose().template head<D>();
        A[s] = linear_part<D>(frames, s, mapped);
    });
    return A;
}

template Index count_degenerate<2>(const std::vector<Mat<2>>&, const std::vector<double>&);
template Index count_degenerate<3>(const std::vector<Mat<3>>&, const std::vector<double>&);
template MapQuality map_quality<2>(const std::vector<Mat<2>>&, const std::vector<double>&);
template MapQuality map_quality<3>(const std::vector<Mat<3>>&, const std::vector<double>&);
template std::vector<Mat<2>> linear_parts<2>(const SimplicialMesh&, const RestFrames<2>&,
                                             const Eigen::MatrixXd&);
template std::vector<Mat<3>> linear_parts<3>(const SimplicialMesh&, const RestFrames<3>&,
                                             const Eigen::MatrixXd&);

}  // namespace sa
