#include "frontends/polycube/polycube_label_cleanup.h"

#include <algorithm>
#include <array>
#include <numeric>

#include "optim/errors.h"

namespace sa {

namespace {

enum class Reason { kNone, kSmall, kFewNeighbours, kOpposite };

Reason why_bad(const PolycubeCharts& charts, int c, double total_area,
               const LabelCleanupOptions& options) {
    if (static_cast<int>(charts.members[c].size()) < options.min_triangles ||
        charts.area[c] < options.min_area_fraction * total_area) {
        return Reason::kSmall;
    }
    if (static_cast<int>(charts.neighbours[c].size()) < options.min_neighbours) {
        return Reason::kFewNeighbours;
    }
    for (const int other : charts.neighbours[c]) {
        // Of an opposite pair the smaller chart goes (the lower index on a tie).
        if (charts.label[other] == (charts.label[c] ^ 1) &&
            (charts.area[c] < charts.area[other] ||
             (charts.area[c] == charts.area[other] && c < other))) {
            return Reason::kOpposite;
        }
    }
    return Reason::kNone;
}

/// The neighbour label that chart c takes.
int merge_label(const PolycubeCharts& charts, int c, const Eigen::MatrixXd& area_vectors) {
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    for (const Index b : charts.members[c]) normal += area_vectors.row(b).transpose();
    int best = -1;
    double best_score = -kInfinity;
    bool best_clean = false;
    for (const int other : charts.neighbours[c]) {
        const int candidate = charts.label[other];
        bool clean = true;
        for (const int n : charts.neighbours[c]) {
            if (charts.label[n] == (candidate ^ 1)) clean = false;
        }
        const double score = normal.dot(label_direction(candidate));
        if ((clean && !best_clean) || (clean == best_clean && score > best_score)) {
            best = candidate;
            best_score = score;
            best_clean = clean;
        }
    }
    return best;
}

/// One pass of the teeth rule (polycube_label_cleanup.h) over the boundary triangles in order;
/// returns how many it relabelled.
Index remove_teeth(const TetBoundary& boundary, const Eigen::MatrixXd& area_vectors,
                   std::vector<int>& labels) {
    Index changed = 0;
    for (Index b = 0; b < boundary.size(); ++b) {
        std::array<int, 3> around{-1, -1, -1};
        for (int i = 0; i < 3; ++i) {
            const Index n = boundary.adjacent[b][i];
            if (n >= 0) around[i] = labels[n];
        }
        for (int i = 0; i < 3; ++i) {
            const int candidate = around[i];
            if (candidate < 0 || candidate == labels[b]) continue;
            const int count = int(std::count(around.begin(), around.end(), candidate));
            const bool opposite =
                std::find(around.begin(), around.end(), candidate ^ 1) != around.end();
            if (count >= 2 && !opposite &&
                area_vectors.row(b).dot(label_direction(candidate).transpose()) > 0.0) {
                labels[b] = candidate;
                ++changed;
                break;
            }
        }
    }
    return changed;
}

}  // namespace

LabelCleanupReport clean_polycube_labels(const TetBoundary& boundary,
                                         const Eigen::MatrixXd& positions, std::vector<int>& labels,
                                         const LabelCleanupOptions& options) {
    return clean_polycube_labels_of_areas(boundary, boundary_area_vectors(boundary, positions),
                                          labels, options);
}

LabelCleanupReport clean_polycube_labels_of_areas(const TetBoundary& boundary,
                                                  const Eigen::MatrixXd& area_vectors,
                                                  std::vector<int>& labels,
                                                  const LabelCleanupOptions& options,
                                                  PolycubeCharts* final_charts) {
    if (options.min_neighbours < 0 || options.min_triangles < 0 ||
        !(options.min_area_fraction >= 0.0 && options.min_area_fraction < 1.0) ||
        options.max_rounds < 0) {
        throw InvalidArgumentError("clean_polycube_labels: options out of range");
    }
    const std::vector<int> before = labels;
    LabelCleanupReport report;
    for (;;) {
        PolycubeCharts charts = polycube_charts_of_areas(boundary, area_vectors, labels);
        if (report.rounds == 0) report.charts_before = charts.size();
        report.charts_after = charts.size();
        const double total_area = std::accumulate(charts.area.begin(), charts.area.end(), 0.0);
        std::vector<int> order(charts.size());
        std::iota(order.begin(), order.end(), 0);
        std::stable_sort(order.begin(), order.end(),
                         [&](int a, int b) { return charts.area[a] < charts.area[b]; });
        std::vector<unsigned char> touched(charts.size(), 0);
        int merged = 0;
        for (const int c : order) {
            const Reason reason = why_bad(charts, c, total_area, options);
            if (reason == Reason::kNone || charts.neighbours[c].empty()) continue;
            // One merge per neighbourhood per round: the charts' data describe the round's start.
            bool free = !touched[c];
            for (const int n : charts.neighbours[c]) free = free && !touched[n];
            if (!free) continue;
            if (report.rounds >= options.max_rounds) break;
            const int label = merge_label(charts, c, area_vectors);
            for (const Index b : charts.members[c]) labels[b] = label;
            touched[c] = 1;
            for (const int n : charts.neighbours[c]) touched[n] = 1;
            ++merged;
            if (reason == Reason::kSmall) ++report.merged_small;
            if (reason == Reason::kFewNeighbours) ++report.merged_few_neighbours;
            if (reason == Reason::kOpposite) ++report.merged_opposite;
        }
        if (merged == 0 && options.remove_teeth && report.rounds < options.max_rounds) {
            const Index teeth = remove_teeth(boundary, area_vectors, labels);
            report.teeth += teeth;
            if (teeth > 0) {
                ++report.rounds;
                continue;
            }
        }
        if (merged == 0) {
            bool clean = true;
            for (int c = 0; c < charts.size(); ++c) {
                clean = clean && why_bad(charts, c, total_area, options) == Reason::kNone;
            }
            report.clean = clean;
            // Nothing merged and no tooth: the labels are still those these charts were made of.
            if (final_charts) *final_charts = std::move(charts);
            break;
        }
        ++report.rounds;
    }
    for (std::size_t b = 0; b < labels.size(); ++b) {
        if (labels[b] != before[b]) ++report.triangles_changed;
    }
    return report;
}

}  // namespace sa
