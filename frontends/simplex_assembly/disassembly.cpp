#include "frontends/simplex_assembly/disassembly.h"

#include <tbb/parallel_for.h>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <random>

#include "frontends/simplex_assembly/bounded_distortion_projection.h"
#include "optim/errors.h"

namespace sa {

Initialization Initialization::bounded_distortion(double K) {
    if (!(K >= 1.0)) {
        throw InvalidArgumentError("bounded-distortion initialization: K = " + std::to_string(K) +
                                   " must be >= 1 (a bound on sigma_max / sigma_min)");
    }
    return Initialization{Kind::kBoundedDistortion, K};
}

std::string to_string(Initialization init) {
    switch (init.kind) {
        case Initialization::Kind::kClosestSimilarity:
            return "similarity";
        case Initialization::Kind::kClosestRotation:
            return "rotation";
        case Initialization::Kind::kIdentity:
            return "identity";
        case Initialization::Kind::kRandomRotation:
            return "random";
        case Initialization::Kind::kBoundedDistortion: {
            if (std::isinf(init.bound)) return "bounded:inf";
            char text[32];  // the shortest form that reads back to the same bound
            const auto end = std::to_chars(text, text + sizeof text, init.bound).ptr;
            return "bounded:" + std::string(text, end);
        }
    }
    return "unknown";
}

Initialization parse_initialization(const std::string& name) {
    for (Initialization i : {Initialization::kClosestSimilarity, Initialization::kClosestRotation,
                             Initialization::kIdentity, Initialization::kRandomRotation}) {
        if (to_string(i) == name) return i;
    }
    const std::string prefix = "bounded:";
    if (name.compare(0, prefix.size(), prefix) == 0) {
        const std::string value = name.substr(prefix.size());
        if (value == "inf" || value == "infinity")
            return Initialization::bounded_distortion(kInfinity);
        char* end = nullptr;
        const double K = value.empty() ? 0.0 : std::strtod(value.c_str(), &end);
        if (!value.empty() && end == value.c_str() + value.size() && std::isfinite(K) && K >= 1.0)
            return Initialization::bounded_distortion(K);
        throw InvalidArgumentError("initialization '" + name +
                                   "': K must be a number >= 1 (the bound on sigma_max / "
                                   "sigma_min) or inf, e.g. bounded:10");
    }
    if (name == "bounded") {
        throw InvalidArgumentError(
            "initialization 'bounded' needs its bound: bounded:K with K >= 1, e.g. bounded:10");
    }
    throw InvalidArgumentError("unknown initialization '" + name +
                               "' (expected similarity, rotation, identity, random or bounded:K)");
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

/// The median of the finite positive values, 1 when there is none.
double median_scale(const std::vector<double>& scales) {
    std::vector<double> finite;
    for (double s : scales) {
        if (std::isfinite(s) && s > 0.0) finite.push_back(s);
    }
    if (finite.empty()) return 1.0;
    std::nth_element(finite.begin(), finite.begin() + finite.size() / 2, finite.end());
    return finite[finite.size() / 2];
}

/// A scale that is not finite or below 1e-3 of the median (a degenerate simplex).
bool degenerate_scale(double scale, double median) {
    return !(std::isfinite(scale) && scale > 1e-3 * median);
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
    switch (init.kind) {
        case Initialization::Kind::kIdentity:
            for (Mat<D>& a : A) a.setIdentity();
            return;
        case Initialization::Kind::kRandomRotation: {
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
        case Initialization::Kind::kClosestRotation:
            tbb::parallel_for(std::size_t(0), A.size(), [&](std::size_t i) {
                A[i] = A[i].allFinite() ? closest_rotation<D>(A[i]) : Mat<D>(Mat<D>::Identity());
            });
            return;
        case Initialization::Kind::kClosestSimilarity: {
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
            const double median = median_scale(scales);
            for (std::size_t i = 0; i < A.size(); ++i) {
                const double s = degenerate_scale(scales[i], median) ? median : scales[i];
                A[i] = s * rotations[i];
            }
            return;
        }
        case Initialization::Kind::kBoundedDistortion: {
            // Projected in place; a degenerate result (a zero or non-finite A_i, or a flat one
            // when K = inf) becomes the closest rotation at the median scale, as above.
            const double K = Initialization::bounded_distortion(init.bound).bound;  // checks K
            std::vector<double> scales(A.size());
            tbb::parallel_for(std::size_t(0), A.size(), [&](std::size_t i) {
                if (!A[i].allFinite()) {
                    A[i].setIdentity();
                    scales[i] = std::nan("");
                    return;
                }
                const Mat<D> projected = project_bounded_distortion<D>(A[i], K);
                scales[i] = Eigen::JacobiSVD<Mat<D>>(projected).singularValues().mean();
                if (degenerate_scale(scales[i], 0.0) || !(projected.determinant() > 0.0)) {
                    A[i] = closest_rotation<D>(A[i]);
                    scales[i] = std::nan("");
                } else {
                    A[i] = projected;
                }
            });
            const double median = median_scale(scales);
            for (std::size_t i = 0; i < A.size(); ++i) {
                if (degenerate_scale(scales[i], median)) A[i] = median * closest_rotation<D>(A[i]);
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
