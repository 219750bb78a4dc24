#include "frontends/polycube/polycube_angle_bound.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "optim/errors.h"

namespace sa {

namespace {

/// Union-find over the corners 3 b + k of the boundary triangles.
struct Corners {
    std::vector<Index> parent;
    explicit Corners(Index n) : parent(n) { std::iota(parent.begin(), parent.end(), Index(0)); }
    Index root(Index c) {
        while (parent[c] != c) c = parent[c] = parent[parent[c]];
        return c;
    }
    void join(Index a, Index b) { parent[root(a)] = root(b); }
};

}  // namespace

std::string WedgeAngleBound::describe() const {
    char line[200];
    std::snprintf(line, sizeof line,
                  "at vertex %lld (0-based) the %s chart's wedge of %.4g degrees (%lld triangle%s) "
                  "must %s to %.0f",
                  static_cast<long long>(vertex), label_name(label).c_str(),
                  rest_angle * 180.0 / M_PI, static_cast<long long>(triangles),
                  triangles == 1 ? "" : "s", rest_angle < image_angle ? "open" : "close",
                  image_angle * 180.0 / M_PI);
    return line;
}

double wedge_distortion_bound(const std::vector<double>& rest_angles, double target) {
    if (rest_angles.empty() || !(target > 0.0)) {
        throw InvalidArgumentError("wedge_distortion_bound: needs rest angles and a target > 0");
    }
    const double sum = std::accumulate(rest_angles.begin(), rest_angles.end(), 0.0);
    const bool opens = sum < target;
    if (opens && target >= double(rest_angles.size()) * M_PI) return kInfinity;
    // The angles' widest range under ratio K: each opens to at most 2 atan(K tan(alpha/2)) and
    // closes to at least 2 atan(tan(alpha/2) / K), both monotone in K.
    auto reaches = [&](double k) {
        double s = 0.0;
        for (const double a : rest_angles) {
            const double t = std::tan(0.5 * a);
            s += 2.0 * std::atan(opens ? k * t : t / k);
        }
        return opens ? s >= target : s <= target;
    };
    if (reaches(1.0)) return 1.0;
    double low = 1.0, high = 2.0;
    while (!reaches(high)) {
        low = high;
        high *= 2.0;
        if (!std::isfinite(high)) return kInfinity;
    }
    while (high > low * (1.0 + 1e-12)) {
        const double mid = std::sqrt(low * high);
        (reaches(mid) ? high : low) = mid;
    }
    return high;
}

PolycubeAngleBound polycube_angle_bound(const TetBoundary& boundary, const PolycubeCharts& charts,
                                        const Eigen::MatrixXd& positions, int keep) {
    const Index n = boundary.size();
    const auto& tri = boundary.triangles;
    auto corner_of = [&](Index b, Index v) {
        for (int k = 0; k < 3; ++k)
            if (tri(b, k) == v) return 3 * b + k;
        return Index(-1);
    };
    // Wedges: a triangle's corner at v joins the corners at v of the triangles of its chart
    // across its two edges at v (side k runs from corner k to k + 1); fans: of any chart.
    Corners wedge(3 * n), fan(3 * n);
    for (Index b = 0; b < n; ++b) {
        for (int k = 0; k < 3; ++k) {
            for (const int side : {k, (k + 2) % 3}) {
                const Index other = boundary.adjacent[b][side];
                const Index c = other < 0 ? -1 : corner_of(other, tri(b, k));
                if (c < 0) continue;
                fan.join(3 * b + k, c);
                if (charts.chart_of[other] == charts.chart_of[b]) wedge.join(3 * b + k, c);
            }
        }
    }
    // A vertex where the boundary pinches (several fans of triangles) has no PolyCube angles
    // that this counting knows: it is left out.
    std::vector<Index> fans_at(positions.rows(), 0);
    for (Index c = 0; c < 3 * n; ++c)
        if (fan.root(c) == c) ++fans_at[tri(c / 3, int(c % 3))];
    // Per wedge (its root corner): the rest angles of its corners.
    std::vector<std::vector<double>> angles(3 * n);
    std::vector<Index> wedges_at(positions.rows(), 0);
    for (Index b = 0; b < n; ++b) {
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d p = positions.row(tri(b, k)).transpose();
            const Eigen::Vector3d e1 = positions.row(tri(b, (k + 1) % 3)).transpose() - p;
            const Eigen::Vector3d e2 = positions.row(tri(b, (k + 2) % 3)).transpose() - p;
            const Index r = wedge.root(3 * b + k);
            if (angles[r].empty()) ++wedges_at[tri(b, k)];
            angles[r].push_back(std::atan2(e1.cross(e2).norm(), e1.dot(e2)));
        }
    }
    // Per vertex, its worst wedge.
    std::vector<WedgeAngleBound> worst_at(positions.rows());
    for (Index c = 0; c < 3 * n; ++c) {
        if (angles[c].empty() || fans_at[tri(c / 3, int(c % 3))] > 1) continue;
        WedgeAngleBound w;
        w.vertex = tri(c / 3, int(c % 3));
        w.chart = charts.chart_of[c / 3];
        w.label = charts.label[w.chart];
        w.wedges = int(wedges_at[w.vertex]);
        w.triangles = Index(angles[c].size());
        w.rest_angle = std::accumulate(angles[c].begin(), angles[c].end(), 0.0);
        const std::vector<double> targets = w.wedges == 1 ? std::vector<double>{2.0 * M_PI}
                                            : w.wedges == 2
                                                ? std::vector<double>{M_PI}
                                                : std::vector<double>{0.5 * M_PI, M_PI, 1.5 * M_PI};
        w.bound = kInfinity;
        for (const double target : targets) {
            const double k = wedge_distortion_bound(angles[c], target);
            if (k < w.bound || w.image_angle == 0.0) {
                w.bound = k;
                w.image_angle = target;
            }
        }
        if (worst_at[w.vertex].vertex < 0 || w.bound > worst_at[w.vertex].bound)
            worst_at[w.vertex] = w;
    }
    PolycubeAngleBound out;
    for (const WedgeAngleBound& w : worst_at) {
        if (w.vertex < 0) continue;
        out.bound = std::max(out.bound, w.bound);
        out.worst.push_back(w);
    }
    const std::size_t kept = std::min(out.worst.size(), std::size_t(std::max(keep, 0)));
    std::partial_sort(out.worst.begin(), out.worst.begin() + kept, out.worst.end(),
                      [](const WedgeAngleBound& a, const WedgeAngleBound& b) {
                          return a.bound > b.bound || (a.bound == b.bound && a.vertex < b.vertex);
                      });
    out.worst.resize(kept);
    return out;
}

}  // namespace sa
