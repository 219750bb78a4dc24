#include "frontends/polycube/polycube_label_repair.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "frontends/polycube/polycube_boundary_monotonicity.h"

namespace sa {

namespace {

/// How far a labelling is from monotone boundaries; lower is better.
struct Score {
    bool usable = false;
    Index backward = 0;   ///< strongly backward edges
    double travel = 0.0;  ///< backward travel (rest units)
    Index changed = 0;    ///< triangles changed by the move (tie-break)
    int turning = 0;

    bool better_than(const Score& o) const {
        if (usable != o.usable) return usable;
        if (backward != o.backward) return backward < o.backward;
        const double scale = std::max(travel, o.travel);
        if (std::abs(travel - o.travel) > 1e-9 * scale) return travel < o.travel;
        return changed < o.changed;
    }
};

struct Evaluated {
    Score score;
    std::vector<NonMonotoneBoundary> turning;
};

/// Scores `labels`, which must already be cleaned.
Evaluated evaluate(const TetBoundary& boundary, const Eigen::MatrixXd& positions,
                   const std::vector<int>& labels, double strong_cosine) {
    Evaluated e;
    const PolycubeCharts charts = polycube_charts(boundary, positions, labels);
    for (int c = 0; c < charts.size(); ++c) {
        if (!(charts.aligned_area[c] > 1e-9 * charts.area[c])) return e;
        for (const int other : charts.neighbours[c]) {
            if (charts.label[other] == (charts.label[c] ^ 1)) return e;
        }
    }
    e.score.usable = true;
    e.turning = non_monotone_boundaries(boundary, positions, labels, charts, strong_cosine);
    e.score.turning = static_cast<int>(e.turning.size());
    for (const NonMonotoneBoundary& t : e.turning) {
        e.score.backward += t.strongly_backward;
        e.score.travel += t.backward_travel;
    }
    return e;
}

/// The triangles of seed's label connected to it within `rings` steps across boundary edges, in
/// order of distance.
std::vector<Index> patch(const TetBoundary& boundary, const std::vector<int>& labels, Index seed,
                         int rings) {
    std::vector<Index> found{seed};
    std::set<Index> seen{seed};
    std::size_t begin = 0;
    for (int r = 0; r < rings; ++r) {
        const std::size_t end = found.size();
        for (std::size_t k = begin; k < end; ++k) {
            for (const Index n : boundary.adjacent[found[k]]) {
                if (n >= 0 && labels[n] == labels[seed] && seen.insert(n).second) {
                    found.push_back(n);
                }
            }
        }
        begin = end;
    }
    return found;
}

}  // namespace

LabelRepairReport repair_turning_boundaries(const TetBoundary& boundary,
                                            const Eigen::MatrixXd& positions,
                                            std::vector<int>& labels,
                                            const LabelRepairOptions& options) {
    LabelRepairReport report;
    const std::vector<int> original = labels;
    Evaluated current = evaluate(boundary, positions, labels, options.strong_cosine);
    report.turning_before = current.score.turning;
    report.backward_before = current.score.backward;
    for (int move = 0; move < options.max_moves && !current.turning.empty(); ++move) {
        // Ties with the current labels on (backward, travel) lose: changed > 0 in every trial.
        Score best = current.score;
        best.changed = 0;
        std::vector<int> best_labels;
        for (const NonMonotoneBoundary& t : current.turning) {
            const auto& edges = t.backward_triangles;
            const int count = std::min<int>(options.edges_per_boundary, int(edges.size()));
            for (int k = 0; k < count; ++k) {
                // Spread over the boundary's backward edges: first, last, between.
                const std::size_t pick =
                    count == 1 ? 0 : std::size_t(k) * (edges.size() - 1) / std::size_t(count - 1);
                for (const Index seed : edges[pick]) {
                    for (int rings = 0; rings <= options.max_rings; ++rings) {
                        const std::vector<Index> region = patch(boundary, labels, seed, rings);
                        std::set<int> candidates;
                        for (const Index b : region) {
                            for (const Index n : boundary.adjacent[b]) {
                                if (n >= 0 && labels[n] != labels[seed] &&
                                    labels[n] != (labels[seed] ^ 1)) {
                                    candidates.insert(labels[n]);
                                }
                            }
                        }
                        for (const int label : candidates) {
                            std::vector<int> trial = labels;
                            for (const Index b : region) trial[b] = label;
                            const LabelCleanupReport cleaned =
                                clean_polycube_labels(boundary, positions, trial, options.cleanup);
                            ++report.trials;
                            if (!cleaned.clean) continue;
                            Evaluated e =
                                evaluate(boundary, positions, trial, options.strong_cosine);
                            e.score.changed = 0;
                            for (std::size_t b = 0; b < trial.size(); ++b) {
                                if (trial[b] != labels[b]) ++e.score.changed;
                            }
                            if (e.score.changed > 0 && e.score.better_than(best)) {
                                best = e.score;
                                best_labels = std::move(trial);
                            }
                        }
                    }
                }
            }
        }
        if (best_labels.empty()) break;
        labels = std::move(best_labels);
        current = evaluate(boundary, positions, labels, options.strong_cosine);
        ++report.moves;
    }
    report.turning_after = current.score.turning;
    report.backward_after = current.score.backward;
    for (std::size_t b = 0; b < labels.size(); ++b) {
        if (labels[b] != original[b]) ++report.triangles_changed;
    }
    return report;
}

}  // namespace sa
