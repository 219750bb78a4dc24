#include "frontends/polycube/polycube_label_repair.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>
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

/// The shape being labelled: rest positions and the boundary triangles' area vectors.
struct Shape {
    const TetBoundary& boundary;
    const Eigen::MatrixXd& positions;
    Eigen::MatrixXd area_vectors;
};

/// Scores `labels`, which must already be cleaned; `charts` are polycube_charts() of them.
Evaluated evaluate(const Shape& shape, const std::vector<int>& labels, const PolycubeCharts& charts,
                   double strong_cosine) {
    Evaluated e;
    for (int c = 0; c < charts.size(); ++c) {
        if (!(charts.aligned_area[c] > 1e-9 * charts.area[c])) return e;
        for (const int other : charts.neighbours[c]) {
            if (charts.label[other] == (charts.label[c] ^ 1)) return e;
        }
    }
    e.score.usable = true;
    e.turning =
        non_monotone_boundaries(shape.boundary, shape.positions, labels, charts, strong_cosine);
    e.score.turning = static_cast<int>(e.turning.size());
    for (const NonMonotoneBoundary& t : e.turning) {
        e.score.backward += t.strongly_backward;
        e.score.travel += t.backward_travel;
    }
    return e;
}

/// A trial move: the triangles of `region` take `label`.
struct Trial {
    std::vector<Index> region;
    int label = kNoLabel;
};

/// `labels` with the trial's move made and cleaned, and their charts; false if the clean-up
/// fails.
bool apply(const Shape& shape, const Trial& trial, const LabelCleanupOptions& cleanup,
           std::vector<int>& labels, PolycubeCharts& charts) {
    for (const Index b : trial.region) labels[b] = trial.label;
    return clean_polycube_labels_of_areas(shape.boundary, shape.area_vectors, labels, cleanup,
                                          &charts)
        .clean;
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

/// The moves tried from `labels` for the current turning boundaries, in a fixed order.
std::vector<Trial> trials_for(const TetBoundary& boundary, const std::vector<int>& labels,
                              const std::vector<NonMonotoneBoundary>& turning,
                              const LabelRepairOptions& options) {
    std::vector<Trial> trials;
    for (const NonMonotoneBoundary& t : turning) {
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
                    for (const int label : candidates) trials.push_back({region, label});
                }
            }
        }
    }
    return trials;
}

}  // namespace

LabelRepairReport repair_turning_boundaries(const TetBoundary& boundary,
                                            const Eigen::MatrixXd& positions,
                                            std::vector<int>& labels,
                                            const LabelRepairOptions& options) {
    LabelRepairReport report;
    const Shape shape{boundary, positions, boundary_area_vectors(boundary, positions)};
    const std::vector<int> original = labels;
    Evaluated current =
        evaluate(shape, labels, polycube_charts_of_areas(boundary, shape.area_vectors, labels),
                 options.strong_cosine);
    report.turning_before = current.score.turning;
    report.backward_before = current.score.backward;
    for (int move = 0; move < options.max_moves && !current.turning.empty(); ++move) {
        const std::vector<Trial> trials = trials_for(boundary, labels, current.turning, options);
        report.trials += static_cast<int>(trials.size());
        // Trials are independent: scored in parallel, compared in order below.
        std::vector<std::optional<Score>> scores(trials.size());
        tbb::parallel_for(std::size_t(0), trials.size(), [&](std::size_t i) {
            std::vector<int> trial = labels;
            PolycubeCharts charts;
            if (!apply(shape, trials[i], options.cleanup, trial, charts)) return;
            Score score = evaluate(shape, trial, charts, options.strong_cosine).score;
            score.changed = 0;
            for (std::size_t b = 0; b < trial.size(); ++b) {
                if (trial[b] != labels[b]) ++score.changed;
            }
            scores[i] = score;
        });
        // The first trial strictly better than all before it and than the current labels: ties
        // with the current labels on (backward, travel) lose, as changed > 0 in every trial.
        Score best = current.score;
        best.changed = 0;
        std::optional<std::size_t> chosen;
        for (std::size_t i = 0; i < trials.size(); ++i) {
            if (scores[i] && scores[i]->changed > 0 && scores[i]->better_than(best)) {
                best = *scores[i];
                chosen = i;
            }
        }
        if (!chosen) break;
        PolycubeCharts charts;
        apply(shape, trials[*chosen], options.cleanup, labels, charts);
        current = evaluate(shape, labels, charts, options.strong_cosine);
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
