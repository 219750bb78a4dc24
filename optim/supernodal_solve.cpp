#include "optim/detail/supernodal_solve.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <string>

#include "optim/errors.h"

namespace sa {

namespace {

/// Splits of the heaviest subtree tried at most; a mesh's tree needs a handful.
constexpr int kMaxSplits = 256;
/// Below this many factor values a solve takes microseconds and a second thread cannot pay.
constexpr double kSmallestSplitWork = 1e5;
/// The split is used only if the estimated critical path is at most this share of the serial
/// solve's work.
constexpr double kLargestUsefulShare = 0.85;

/// How far ahead of the column being read the substitutions prefetch the factor: 256 values
/// (2 KB). The factor streams from memory after a factorization, and the hardware prefetcher
/// stops at page boundaries (bench/triangular_solve.cpp --refactor measures it on 3D factors;
/// docs/measurements.md, "Triangular solves alone"); farther ahead was no better.
constexpr int kPrefetchAhead = 256;

/// Prefetches the n values from `from` on (one request per 64-byte line).
void prefetch(const double* from, int n) {
    for (int p = 0; p < n; p += 8) __builtin_prefetch(from + p);
}

/// Sum of a[i] * b[i] over n entries in eight lanes (entry i in lane i mod 8) summed pairwise:
/// the order of the operations depends on n only, not on where the arrays lie in memory
/// (Eigen's dot product starts its vectors at the first aligned entry), so that a solve gives
/// the same bits for the same factor wherever it was allocated.
double fixed_order_dot(const double* __restrict a, const double* __restrict b, int n) {
    constexpr int kLanes = 8;
    double lane[kLanes] = {};
    const int whole = n / kLanes * kLanes;
    for (int i = 0; i < whole; i += kLanes)
        for (int l = 0; l < kLanes; ++l) lane[l] += a[i + l] * b[i + l];
    for (int l = 0; l < n - whole; ++l) lane[l] += a[whole + l] * b[whole + l];
    return ((lane[0] + lane[4]) + (lane[2] + lane[6])) +
           ((lane[1] + lane[5]) + (lane[3] + lane[7]));
}

/// Forward substitution through one supernode: its m x k column-major block L (leading
/// dimension m, the k x k lower triangle on top) and x of m entries, x[0, k) the right-hand side
/// of its columns on entry and their solution y = L11^-1 x on exit, x[k, m) zero on entry and
/// -L21 y on exit. Column by column, an axpy each down the whole column: one pass over the
/// block, in order. Eigen's blocked triangular solve and gemv, a triangle pass then a rectangle
/// pass, and panels of eight columns updating the rows below at once were no faster, and the
/// panels slower on factors of many narrow supernodes (bench/triangular_solve.cpp --refactor;
/// docs/measurements.md, "Triangular solves alone").
void supernode_forward(const double* L, int m, int k, double* x) {
    for (int j = 0; j < k; ++j) {
        const double* column = L + std::ptrdiff_t(j) * m;
        prefetch(column + kPrefetchAhead, m);
        const double xj = x[j] / column[j];
        x[j] = xj;
        Eigen::Map<Eigen::VectorXd>(x + j + 1, m - j - 1) -=
            xj * Eigen::Map<const Eigen::VectorXd>(column + j + 1, m - j - 1);
    }
}

/// Backward substitution through one supernode: x[k, m) the solution at the rows below its
/// columns, x[0, k) the right-hand side of its columns on entry and on exit their solution of
/// L11^T x = rhs - L21^T x_below. Column by column from the last, a dot product each.
void supernode_backward(const double* L, int m, int k, double* x) {
    for (int j = k - 1; j >= 0; --j) {
        const double* column = L + std::ptrdiff_t(j) * m;
        prefetch(column - kPrefetchAhead, m);
        x[j] = (x[j] - fixed_order_dot(column + j + 1, x + j + 1, m - j - 1)) / column[j];
    }
}

}  // namespace

SupernodalSolve::SupernodalSolve(const SupernodalStructure& structure)
    : num_columns_(structure.num_columns) {
    const int ns = structure.num_supernodes;
    if (ns < 0 || num_columns_ < 0 ||
        (ns > 0 && (structure.first_column == nullptr || structure.row_start == nullptr ||
                    structure.value_start == nullptr || structure.rows == nullptr))) {
        throw InvalidArgumentError("supernodal solve: incomplete factor structure");
    }
    first_column_.assign(structure.first_column, structure.first_column + ns + 1);
    row_start_.assign(structure.row_start, structure.row_start + ns + 1);
    value_start_.assign(structure.value_start, structure.value_start + ns + 1);
    rows_.assign(structure.rows, structure.rows + row_start_[ns]);
    if (first_column_[0] != 0 || first_column_[ns] != num_columns_) {
        throw InvalidArgumentError("supernodal solve: supernodes do not cover the columns");
    }

    // The supernodal elimination tree: the parent of s holds s's first row below its columns.
    std::vector<int> supernode_of_column(num_columns_);
    for (int s = 0; s < ns; ++s) {
        if (first_column_[s + 1] <= first_column_[s] ||
            row_start_[s + 1] - row_start_[s] < first_column_[s + 1] - first_column_[s]) {
            throw InvalidArgumentError("supernodal solve: supernode " + std::to_string(s) +
                                       " is malformed");
        }
        for (int c = first_column_[s]; c < first_column_[s + 1]; ++c) supernode_of_column[c] = s;
    }
    std::vector<int> parent(ns, -1), first_descendant(ns), descendants(ns, 1);
    std::vector<double> work(ns), subtree_work(ns);
    std::vector<std::vector<int>> children(ns);
    std::vector<int> roots;
    double total = 0.0;
    bool postordered = true;
    for (int s = 0; s < ns; ++s) {
        const int k = first_column_[s + 1] - first_column_[s];
        const int m = row_start_[s + 1] - row_start_[s];
        work[s] = double(m) * k + m;  // values, and row indices, read per substitution
        total += work[s];
        first_descendant[s] = s;
    }
    for (int s = 0; s < ns; ++s) {
        subtree_work[s] += work[s];
        const int k = first_column_[s + 1] - first_column_[s];
        if (row_start_[s + 1] - row_start_[s] > k) {
            const int p = supernode_of_column[rows_[row_start_[s] + k]];
            if (p <= s) throw InvalidArgumentError("supernodal solve: the tree is not ordered");
            parent[s] = p;
            children[p].push_back(s);
            subtree_work[p] += subtree_work[s];
            descendants[p] += descendants[s];
            first_descendant[p] = std::min(first_descendant[p], first_descendant[s]);
        } else {
            roots.push_back(s);
        }
        postordered = postordered && descendants[s] == s - first_descendant[s] + 1;
    }
    if (!postordered || total < kSmallestSplitWork) {
        for (int s = 0; s < ns; ++s) top_.push_back(s);
    } else {
        // Greedy: split the heaviest candidate subtree (its root goes to the top, its children
        // become candidates) while that may lower top + max(group); fill the two groups largest
        // first, each into the lighter one. Ties go by supernode index, so the cut is a function
        // of the structure alone.
        auto heavier = [&](int a, int b) {
            return subtree_work[a] != subtree_work[b] ? subtree_work[a] > subtree_work[b] : a < b;
        };
        std::vector<int> candidates = roots, best_candidates;
        std::vector<int> best_group;
        double kept = 0.0, best_cost = total;
        for (int split = 0; split <= kMaxSplits && !candidates.empty(); ++split) {
            std::sort(candidates.begin(), candidates.end(), heavier);
            double load[2] = {0.0, 0.0};
            std::vector<int> group(candidates.size());
            for (std::size_t i = 0; i < candidates.size(); ++i) {
                group[i] = load[1] < load[0] ? 1 : 0;
                load[group[i]] += subtree_work[candidates[i]];
            }
            const double cost = kept + std::max(load[0], load[1]);
            if (cost < best_cost) {
                best_cost = cost;
                best_candidates = candidates;
                best_group = group;
            }
            const int heaviest = candidates.front();
            if (children[heaviest].empty()) break;
            kept += work[heaviest];
            if (kept >= best_cost) break;
            candidates.erase(candidates.begin());
            candidates.insert(candidates.end(), children[heaviest].begin(),
                              children[heaviest].end());
        }
        if (best_cost > kLargestUsefulShare * total) best_candidates.clear();

        std::vector<char> in_group(ns, 0);
        for (std::size_t i = 0; i < best_candidates.size(); ++i) {
            const int root = best_candidates[i];
            Group& g = groups_[best_group[i]];
            const int end_column = first_column_[root + 1];
            for (int s = first_descendant[root]; s <= root; ++s) {
                in_group[s] = 1;
                g.supernodes.push_back(s);
                const int* below =
                    rows_.data() + row_start_[s] + (first_column_[s + 1] - first_column_[s]);
                const int* end = rows_.data() + row_start_[s + 1];
                g.own_rows.push_back(int(std::lower_bound(below, end, end_column) - below));
            }
        }
        for (Group& g : groups_) {
            // Subtrees were appended largest first; eliminate them in column order.
            std::vector<int> order(g.supernodes.size());
            for (std::size_t i = 0; i < order.size(); ++i) order[i] = int(i);
            std::sort(order.begin(), order.end(),
                      [&](int a, int b) { return g.supernodes[a] < g.supernodes[b]; });
            std::vector<int> supernodes(order.size()), own_rows(order.size());
            for (std::size_t i = 0; i < order.size(); ++i) {
                supernodes[i] = g.supernodes[order[i]];
                own_rows[i] = g.own_rows[order[i]];
            }
            g.supernodes.swap(supernodes);
            g.own_rows.swap(own_rows);
        }
        for (int s = 0; s < ns; ++s)
            if (!in_group[s]) top_.push_back(s);
    }

    int tallest = 0;
    for (int s = 0; s < ns; ++s) tallest = std::max(tallest, row_start_[s + 1] - row_start_[s]);
    double top_work = 0.0;
    for (int s : top_) {
        top_work += work[s];
        for (int c = first_column_[s]; c < first_column_[s + 1]; ++c) top_rows_.push_back(c);
    }
    serial_share_ = total > 0.0 ? top_work / total : 1.0;
    top_scratch_.resize(tallest);
    for (Group& g : groups_) {
        if (g.supernodes.empty()) continue;
        g.top_updates.assign(num_columns_, 0.0);
        g.scratch.resize(tallest);
    }
}

double SupernodalSolve::serial_share() const {
    return serial_share_;
}

void SupernodalSolve::forward(int s, int own_rows, const double* values, double* b, double* outside,
                              Eigen::VectorXd& scratch) const {
    const int c0 = first_column_[s], k = first_column_[s + 1] - c0;
    const int p0 = row_start_[s], m = row_start_[s + 1] - p0;
    double* x = scratch.data();
    std::copy(b + c0, b + c0 + k, x);
    std::fill(x + k, x + m, 0.0);
    supernode_forward(values + value_start_[s], m, k, x);
    std::copy(x, x + k, b + c0);
    const int* r = rows_.data() + p0 + k;
    const double* update = x + k;  // -L21 y
    for (int i = 0; i < own_rows; ++i) b[r[i]] += update[i];
    for (int i = own_rows; i < m - k; ++i) outside[r[i]] -= update[i];
}

void SupernodalSolve::backward(int s, const double* values, double* b,
                               Eigen::VectorXd& scratch) const {
    const int c0 = first_column_[s], k = first_column_[s + 1] - c0;
    const int p0 = row_start_[s], m = row_start_[s + 1] - p0;
    double* x = scratch.data();
    std::copy(b + c0, b + c0 + k, x);
    const int* r = rows_.data() + p0 + k;
    for (int i = 0; i < m - k; ++i) x[k + i] = b[r[i]];
    supernode_backward(values + value_start_[s], m, k, x);
    std::copy(x, x + k, b + c0);
}

void SupernodalSolve::run_group(const Group& group, const double* values, double* b,
                                bool forward_pass) const {
    const std::size_t count = group.supernodes.size();
    if (forward_pass) {
        double* outside = group.top_updates.data();
        for (int r : top_rows_) outside[r] = 0.0;
        for (std::size_t i = 0; i < count; ++i)
            forward(group.supernodes[i], group.own_rows[i], values, b, outside, group.scratch);
    } else {
        for (std::size_t i = count; i-- > 0;)
            backward(group.supernodes[i], values, b, group.scratch);
    }
}

void SupernodalSolve::solve_in_place(const double* values, double* b) const {
    // A split fills both groups (its cost is below the serial one only with two subtrees or
    // more, and the second goes to the empty group), or none.
    const bool split = !groups_[0].supernodes.empty();
    auto both_groups = [&](bool forward_pass) {
        tbb::parallel_invoke([&] { run_group(groups_[0], values, b, forward_pass); },
                             [&] { run_group(groups_[1], values, b, forward_pass); });
    };
    if (split) {
        both_groups(true);
        for (const Group& g : groups_)
            for (int r : top_rows_) b[r] -= g.top_updates[r];
    }
    for (int s : top_) {
        const int k = first_column_[s + 1] - first_column_[s];
        forward(s, row_start_[s + 1] - row_start_[s] - k, values, b, nullptr, top_scratch_);
    }
    for (auto s = top_.rbegin(); s != top_.rend(); ++s) backward(*s, values, b, top_scratch_);
    if (split) both_groups(false);
}

}  // namespace sa
