#include "frontends/hex/hex_extraction.h"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "optim/errors.h"

namespace sa {

namespace {

constexpr double kTolerance = 1e-9;
constexpr int kLimit = 1 << 20;  ///< doubled grid coordinates stay within +-kLimit

/// A point of the doubled grid (corners even, cell centres odd in every coordinate).
std::uint64_t key(const Eigen::Vector3i& doubled) {
    std::uint64_t k = 0;
    for (int i = 0; i < 3; ++i) k = (k << 21) | std::uint64_t(doubled[i] + kLimit);
    return k;
}

Eigen::Vector3i from_key(std::uint64_t k) {
    Eigen::Vector3i doubled;
    for (int i = 2; i >= 0; --i) {
        doubled[i] = int(k & ((1u << 21) - 1)) - kLimit;
        k >>= 21;
    }
    return doubled;
}

struct Location {
    Index tet = -1;
    double depth = -1.0;  ///< the smallest barycentric coordinate
    Eigen::Vector4d barycentric;
};

}  // namespace

HexExtraction extract_hexes(const Eigen::MatrixXi& tets, const Eigen::MatrixXd& grid,
                            const Eigen::MatrixXd& rest) {
    if (tets.cols() != 4 || grid.cols() != 3 || rest.cols() != 3 || grid.rows() != rest.rows() ||
        (tets.size() > 0 && (tets.minCoeff() < 0 || tets.maxCoeff() >= grid.rows()))) {
        throw InvalidArgumentError(
            "extract_hexes: expected #T x 4 tetrahedra and #V x 3 grid and "
            "rest positions");
    }
    if (!grid.allFinite() || grid.cwiseAbs().maxCoeff() >= kLimit / 2 - 1)
        throw InvalidArgumentError("extract_hexes: grid positions must be finite and within 2^19");

    std::unordered_map<std::uint64_t, Location> located;
    located.reserve(static_cast<std::size_t>(2 * tets.rows()));
    for (Index t = 0; t < tets.rows(); ++t) {
        Eigen::Matrix3d edges;
        const Eigen::Vector3d origin = grid.row(tets(t, 0)).transpose();
        Eigen::Vector3d low = origin, high = origin;
        for (int k = 1; k < 4; ++k) {
            const Eigen::Vector3d x = grid.row(tets(t, k)).transpose();
            edges.col(k - 1) = x - origin;
            low = low.cwiseMin(x);
            high = high.cwiseMax(x);
        }
        bool invertible = false;
        Eigen::Matrix3d inverse;
        edges.computeInverseWithCheck(inverse, invertible);
        if (!invertible) continue;
        Eigen::Vector3i from, to;
        for (int i = 0; i < 3; ++i) {
            from[i] = int(std::ceil(2.0 * low[i] - 1e-6));
            to[i] = int(std::floor(2.0 * high[i] + 1e-6));
        }
        for (int x = from[0]; x <= to[0]; ++x) {
            for (int y = from[1]; y <= to[1]; ++y) {
                // A corner has even coordinates, a centre odd ones: all three of one parity.
                if (((x ^ y) & 1) != 0) continue;
                for (int z = from[2]; z <= to[2]; ++z) {
                    if (((x ^ z) & 1) != 0) continue;
                    const Eigen::Vector3d point(0.5 * x, 0.5 * y, 0.5 * z);
                    const Eigen::Vector3d l = inverse * (point - origin);
                    const Eigen::Vector4d barycentric(1.0 - l.sum(), l[0], l[1], l[2]);
                    const double depth = barycentric.minCoeff();
                    if (depth < -kTolerance) continue;
                    Location& best = located[key({x, y, z})];
                    if (best.tet < 0 || depth > best.depth) best = {t, depth, barycentric};
                }
            }
        }
    }

    std::vector<std::uint64_t> centres;
    for (const auto& [k, location] : located) {
        if ((from_key(k)[0] & 1) != 0) centres.push_back(k);
    }
    std::sort(centres.begin(), centres.end());  // (i, j, k) in increasing order

    // Corner c of the cell at doubled centre (x, y, z): the unit cube's corner layout.
    static constexpr std::array<std::array<int, 3>, 8> kCorner = {
        {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
    HexExtraction out;
    std::unordered_map<std::uint64_t, Index> vertex_of;
    std::vector<std::array<Index, 8>> hexes;
    std::vector<std::uint64_t> vertex_keys;
    for (const std::uint64_t centre : centres) {
        const Eigen::Vector3i c = from_key(centre);
        std::array<std::uint64_t, 8> corners;
        bool complete = true;
        for (int k = 0; k < 8; ++k) {
            const Eigen::Vector3i doubled(c[0] - 1 + 2 * kCorner[k][0],
                                          c[1] - 1 + 2 * kCorner[k][1],
                                          c[2] - 1 + 2 * kCorner[k][2]);
            corners[k] = key(doubled);
            if (located.find(corners[k]) == located.end()) complete = false;
        }
        if (!complete) {
            ++out.cells_with_missing_corners;
            continue;
        }
        std::array<Index, 8> hex;
        for (int k = 0; k < 8; ++k) {
            auto [it, inserted] = vertex_of.try_emplace(corners[k], Index(vertex_keys.size()));
            if (inserted) vertex_keys.push_back(corners[k]);
            hex[k] = it->second;
        }
        hexes.push_back(hex);
    }

    const Index n = static_cast<Index>(vertex_keys.size());
    out.mesh.positions.resize(n, 3);
    out.grid_points.resize(n, 3);
    for (Index v = 0; v < n; ++v) {
        const Location& where = located.at(vertex_keys[v]);
        Eigen::Vector4d weights = where.barycentric.cwiseMax(0.0);
        weights /= weights.sum();
        Eigen::Vector3d x = Eigen::Vector3d::Zero();
        for (int k = 0; k < 4; ++k) x += weights[k] * rest.row(tets(where.tet, k)).transpose();
        out.mesh.positions.row(v) = x.transpose();
        out.grid_points.row(v) = (from_key(vertex_keys[v]) / 2).transpose();
    }
    out.mesh.hexes.resize(static_cast<Eigen::Index>(hexes.size()), 8);
    for (std::size_t h = 0; h < hexes.size(); ++h)
        for (int k = 0; k < 8; ++k) out.mesh.hexes(Eigen::Index(h), k) = hexes[h][k];
    return out;
}

}  // namespace sa
