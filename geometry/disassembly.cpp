#include "geometry/disassembly.h"

#include <tbb/parallel_for.h>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <random>

#include "optim/errors.h"

namespace sa {

std::string to_string(Initialization init) {
    switch (init) {
        case Initialization::kClosestSimilarity:
            return "similarity";
        case Initialization::kClosestRotation:
            return "rotation";
        case Initialization::kIdentity:
            return "identity";
        case Initialization::kRandomRotation:
            return "random";
    }
    return "unknown";
}

Initialization parse_initialization(const std::string& name) {
    for (Initialization i : {Initialization::kClosestSimilarity, Initialization::kClosestRotation,
                             Initialization::kIdentity, Initialization::kRandomRotation}) {
        if (to_string(i) == name) return i;
    }
    throw InvalidArgumentError("unknown initialization '" + name +
                               "' (expected similarity, rotation, identity or random)");
}

namespace {

/// Rotation part and mean singular value, the smallest singular direction flipped when
/// det A < 0.
template <int D>
std::pair<Mat<D>, double> signed_polar(const Mat<D>& A) {
    const Eigen::JacobiSVD<Mat<D>> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Mat<D> U = svd.matrixU();
    const Mat<D>& V = svd.matrixV();
    if ((U * V.transpose()).determinant() < 0.0) U.col(D - 1) *= -1.0;  // smallest direction
    return {U * V.transpose(), svd.singularValues().mean()};
}

}  // namespace

template <int D>
Mat<D> closest_rotation(const Mat<D>& A) {
    return signed_polar<D>(A).first;
}

template <int D>
Mat<D> closest_similarity(const Mat<D>& A) {
    const auto [R, s] = signed_polar<D>(A);
    return s * R;
}

template <int D>
void project_linear_parts(std::vector<Mat<D>>& A, Initialization init, std::uint64_t seed) {
    switch (init) {
        case Initialization::kIdentity:
            for (Mat<D>& a : A) a.setIdentity();
            return;
        case Initialization::kRandomRotation: {
            std::mt19937_64 rng(seed);
            std::uniform_real_distribution<double> unit(0.0,
                                                        1.0);  // Figure 6(d): entries in [0, 1]
            for (Mat<D>& a : A) {
                Mat<D> r;
                for (int i = 0; i < D * D; ++i) r(i) = unit(rng);
                a = closest_rotation<D>(r);
            }
            return;
        }
        case Initialization::kClosestRotation:
            tbb::parallel_for(std::size_t(0), A.size(), [&](std::size_t i) {
                A[i] = A[i].allFinite() ? closest_rotation<D>(A[i]) : Mat<D>(Mat<D>::Identity());
            });
            return;
        case Initialization::kClosestSimilarity: {
            std::vector<Mat<D>> rotations(A.size());
            std::vector<double> scales(A.size());
            tbb::parallel_for(std::size_t(0), A.size(), [&](std::size_t i) {
                if (A[i].allFinite()) {
                    std::tie(rotations[i], scales[i]) = signed_polar<D>(A[i]);
                } else {
                    rotations[i].setIdentity();
                    scales[i] = std::nan("");
                }
            });
            std::vector<double> finite;
            for (double s : scales) {
                if (std::isfinite(s) && s > 0.0) finite.push_back(s);
            }
            double median = 1.0;
            if (!finite.empty()) {
                std::nth_element(finite.begin(), finite.begin() + finite.size() / 2, finite.end());
                median = finite[finite.size() / 2];
            }
            for (std::size_t i = 0; i < A.size(); ++i) {
                const double s =
                    std::isfinite(scales[i]) && scales[i] > 1e-3 * median ? scales[i] : median;
                A[i] = s * rotations[i];
            }
            return;
        }
    }
}

template Mat<2> closest_rotation<2>(const Mat<2>&);
template Mat<3> closest_rotation<3>(const Mat<3>&);
template Mat<2> closest_similarity<2>(const Mat<2>&);
template Mat<3> closest_similarity<3>(const Mat<3>&);
template void project_linear_parts<2>(std::vector<Mat<2>>&, Initialization, std::uint64_t);
template void project_linear_parts<3>(std::vector<Mat<3>>&, Initialization, std::uint64_t);

}  // namespace sa
