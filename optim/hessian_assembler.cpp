#include "optim/detail/hessian_assembler.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <sstream>

#include "optim/detail/prefault.h"
#include "optim/stopwatch.h"

namespace sa {

namespace {

/// Element `element` of term `term` uses a free variable as its `local`-th variable.
struct Incidence {
    TermId term;
    Index element;
    int local;
};

constexpr Index kColumnGrain = 1024;

/// Exclusive prefix sum in place: counts [c0, c1, ...] -> offsets [0, c0, c0 + c1, ...].
void counts_to_offsets(std::vector<std::int64_t>& v) {
    std::int64_t sum = 0;
    for (auto& c : v) {
        const std::int64_t count = c;
        c = sum;
        sum += count;
    }
}

}  // namespace

HessianAssembler::HessianAssembler(const Problem& problem)
    : problem_id_(problem.id()), structure_version_(problem.structure_version()) {
    const Index n = problem.num_variables();
    const int num_terms = problem.num_terms();
    // Per term, out of the loops below: where its elements' variables and slots are, instead of
    // virtual calls for every incidence.
    std::vector<TermLayout> layout(num_terms);
    for (TermId t = 0; t < num_terms; ++t) layout[t] = problem.term(t).layout();
    auto element_variables = [&](TermId t, Index e) {
        return layout[t].variables + layout[t].begin(e);
    };
    // The local rows [first, first + block) that local column `local` of element e couples with.
    auto block_first = [&](TermId t, Index e, int local) {
        return local - local % layout[t].block_of(e);
    };

    // Free variables: used by some term and not fixed, numbered in variable order.
    std::vector<unsigned char> used(n, 0);
    for (TermId t = 0; t < num_terms; ++t) {
        const std::int64_t entries = layout[t].num_entries();
        for (std::int64_t k = 0; k < entries; ++k) used[layout[t].variables[k]] = 1;
    }
    free_of_variable_.assign(n, -1);
    for (Index v = 0; v < n; ++v) {
        if (used[v] && !problem.is_fixed(v)) {
            free_of_variable_[v] = static_cast<Index>(variable_of_free_.size());
            variable_of_free_.push_back(v);
        }
    }
    const Index nf = num_free();

    // Slots: every term has gradient slots; non-quadratic terms also Hessian slots.
    gradient_offset_.resize(num_terms);
    hessian_offset_.resize(num_terms);
    std::int64_t gradient_size = 0, hessian_size = 0;
    for (TermId t = 0; t < num_terms; ++t) {
        const bool quadratic = problem.term(t).is_quadratic();
        gradient_offset_[t] = gradient_size;
        gradient_size += layout[t].num_entries();
        hessian_offset_[t] = quadratic ? -1 : hessian_size;
        if (!quadratic) hessian_size += layout[t].num_hessian_slots();
    }
    assign_prefaulted(gradient_slots_, std::size_t(gradient_size), 0.0);
    assign_prefaulted(hessian_slots_, std::size_t(hessian_size), 0.0);

    // Incidences of each free variable, ordered by (term, element, local index).
    std::vector<std::int64_t> incidence_begin(nf + 1, 0);
    for (TermId t = 0; t < num_terms; ++t) {
        const std::int64_t entries = layout[t].num_entries();
        for (std::int64_t k = 0; k < entries; ++k) {
            const Index j = free_of_variable_[layout[t].variables[k]];
            if (j >= 0) ++incidence_begin[j];
        }
    }
    counts_to_offsets(incidence_begin);
    std::vector<Incidence> incidences(incidence_begin[nf]);
    {
        std::vector<std::int64_t> cursor(incidence_begin.begin(), incidence_begin.end() - 1);
        for (TermId t = 0; t < num_terms; ++t) {
            const Index ne = layout[t].num_elements;
            const Index* vars = layout[t].variables;
            for (Index e = 0; e < ne; ++e) {
                const int n = layout[t].arity_of(e);
                for (int k = 0; k < n; ++k, ++vars) {
                    const Index j = free_of_variable_[*vars];
                    if (j >= 0) incidences[cursor[j]++] = Incidence{t, e, k};
                }
            }
        }
    }

    // Gradient gather lists: the incidences themselves.
    gradient_source_begin_ = incidence_begin;
    assign_prefaulted(gradient_source_, incidences.size(), std::int64_t{0});
    tbb::parallel_for(std::size_t(0), incidences.size(), [&](std::size_t p) {
        const Incidence& in = incidences[p];
        gradient_source_[p] =
            gradient_offset_[in.term] + layout[in.term].begin(in.element) + in.local;
    });

    // Quadratic terms: evaluated and projected (unless convex; negative curvature clamped to
    // zero) once, here; their contributions are summed per entry below.
    const Eigen::VectorXd& x = problem.variables();
    std::vector<int> quadratic_index(num_terms, -1);
    std::vector<std::vector<double>> quadratic_hessians;
    for (TermId t = 0; t < num_terms; ++t) {
        const Term& term = problem.term(t);
        if (!term.is_quadratic()) continue;
        std::vector<double> g;
        assign_prefaulted(g, std::size_t(layout[t].num_entries()), 0.0);
        std::vector<double>& h = quadratic_hessians.emplace_back();
        assign_prefaulted(h, std::size_t(layout[t].num_hessian_slots()), 0.0);
        term.evaluate(x, 1.0, g.data(), h.data());
        if (!term.is_convex()) term.project(x, h.data(), ProjectionMode::kClamp, 0.0);
        quadratic_index[t] = static_cast<int>(quadratic_parts_.size());
        quadratic_parts_.push_back({t, {}, {}});
    }
    const std::size_t num_quadratic = quadratic_parts_.size();

    // Column passes. Rows i >= j of column j are the free variables sharing an element with j;
    // `slot[i]` is row i's place in the column being visited, `seen[i]` the visit that last
    // saw row i (so that no per-column clearing is needed).
    struct ColumnScratch {
        std::vector<std::int64_t> seen;
        std::vector<Index> slot;
        std::vector<Index> rows;
        std::vector<std::int64_t> cursor;
        std::vector<double> quadratic_value;  ///< num_quadratic x column length
        std::vector<unsigned char> quadratic_touched;
        std::int64_t visit = 0;
    };
    tbb::enumerable_thread_specific<ColumnScratch> scratches([nf] {
        ColumnScratch c;
        c.seen.assign(nf, -1);
        c.slot.assign(nf, 0);
        return c;
    });
    auto collect_rows = [&](Index j, ColumnScratch& c) {
        const std::int64_t visit = c.visit++;
        c.rows.clear();
        c.rows.push_back(j);  // the diagonal; the candidates below are all i > j
        for (std::int64_t p = incidence_begin[j]; p < incidence_begin[j + 1]; ++p) {
            const Incidence& in = incidences[p];
            const Index* vars = element_variables(in.term, in.element);
            const int first = block_first(in.term, in.element, in.local);
            const int block = layout[in.term].block_of(in.element);
            for (int r = first; r < first + block; ++r) {
                const Index i = free_of_variable_[vars[r]];
                if (i > j && c.seen[i] != visit) {
                    c.seen[i] = visit;
                    c.rows.push_back(i);
                }
            }
        }
    };
    // Visits every (element Hessian entry -> place in column j) contribution, in the fixed order
    // (term, element, local column, local row), each with its place in the term's Hessian
    // slots (term.h); c.slot must hold column j's places.
    auto for_each_contribution = [&](Index j, const ColumnScratch& c, auto&& visit) {
        for (std::int64_t p = incidence_begin[j]; p < incidence_begin[j + 1]; ++p) {
            const Incidence& in = incidences[p];
            const Index* vars = element_variables(in.term, in.element);
            const int first = block_first(in.term, in.element, in.local);
            const int block = layout[in.term].block_of(in.element);
            for (int r = first; r < first + block; ++r) {
                const Index i = free_of_variable_[vars[r]];
                if (i < j) continue;
                visit(c.slot[i], in, hessian_slot(block, in.local, r));
            }
        }
    };
    // Pass 1: column lengths.
    std::vector<std::int64_t> column_begin(nf + 1, 0);
    tbb::parallel_for(tbb::blocked_range<Index>(0, nf, kColumnGrain),
                      [&](const tbb::blocked_range<Index>& range) {
                          ColumnScratch& c = scratches.local();
                          for (Index j = range.begin(); j != range.end(); ++j) {
                              collect_rows(j, c);
                              column_begin[j] = static_cast<std::int64_t>(c.rows.size());
                          }
                      });
    counts_to_offsets(column_begin);
    const std::int64_t nnz = column_begin[nf];
    if (nnz > std::numeric_limits<int>::max()) {
        std::ostringstream msg;
        msg << "Hessian has " << nnz << " nonzeros in its lower triangle; at most "
            << std::numeric_limits<int>::max() << " are supported";
        throw InvalidArgumentError(msg.str());
    }
    hessian_.resize(nf, nf);
    hessian_.resizeNonZeros(static_cast<Index>(nnz));
    prefault(hessian_.valuePtr(), std::size_t(nnz) * sizeof(double));
    prefault(hessian_.innerIndexPtr(), std::size_t(nnz) * sizeof(int));
    for (Index j = 0; j <= nf; ++j) hessian_.outerIndexPtr()[j] = static_cast<int>(column_begin[j]);
    int* const pattern = hessian_.innerIndexPtr();

    // Pass 2: the pattern; the number of non-quadratic contributions to each entry, and of the
    // entries of each column that each quadratic term touches.
    assign_prefaulted(entry_source_begin_, std::size_t(nnz + 1), std::int64_t{0});
    std::vector<std::vector<std::int64_t>> quadratic_begin(num_quadratic,
                                                           std::vector<std::int64_t>(nf + 1, 0));
    tbb::parallel_for(
        tbb::blocked_range<Index>(0, nf, kColumnGrain),
        [&](const tbb::blocked_range<Index>& range) {
            ColumnScratch& c = scratches.local();
            for (Index j = range.begin(); j != range.end(); ++j) {
                collect_rows(j, c);
                std::sort(c.rows.begin(), c.rows.end());
                const std::size_t length = c.rows.size();
                for (std::size_t k = 0; k < length; ++k) {
                    pattern[column_begin[j] + std::int64_t(k)] = static_cast<int>(c.rows[k]);
                    c.slot[c.rows[k]] = static_cast<Index>(k);
                }
                c.quadratic_touched.assign(num_quadratic * length, 0);
                for_each_contribution(j, c, [&](Index k, const Incidence& in, std::int64_t) {
                    const int q = quadratic_index[in.term];
                    if (q < 0) {
                        ++entry_source_begin_[column_begin[j] + k];
                    } else if (!c.quadratic_touched[q * length + k]) {
                        c.quadratic_touched[q * length + k] = 1;
                        ++quadratic_begin[q][j];
                    }
                });
            }
        });
    counts_to_offsets(entry_source_begin_);
    assign_prefaulted(entry_source_, std::size_t(entry_source_begin_[nnz]), std::int64_t{0});
    for (std::size_t q = 0; q < num_quadratic; ++q) {
        counts_to_offsets(quadratic_begin[q]);
        quadratic_parts_[q].position.resize(quadratic_begin[q][nf]);
        quadratic_parts_[q].value.resize(quadratic_begin[q][nf]);
    }

    // Pass 3: the gather lists of the non-quadratic terms, per entry, and the sums of the
    // quadratic ones.
    tbb::parallel_for(
        tbb::blocked_range<Index>(0, nf, kColumnGrain),
        [&](const tbb::blocked_range<Index>& range) {
            ColumnScratch& c = scratches.local();
            for (Index j = range.begin(); j != range.end(); ++j) {
                const std::int64_t begin = column_begin[j];
                const std::size_t length = std::size_t(column_begin[j + 1] - begin);
                for (std::size_t k = 0; k < length; ++k)
                    c.slot[pattern[begin + std::int64_t(k)]] = static_cast<Index>(k);
                // Entries of column j are filled only from column j: a local cursor suffices.
                c.cursor.assign(entry_source_begin_.begin() + begin,
                                entry_source_begin_.begin() + begin + std::int64_t(length));
                c.quadratic_value.assign(num_quadratic * length, 0.0);
                c.quadratic_touched.assign(num_quadratic * length, 0);
                for_each_contribution(j, c, [&](Index k, const Incidence& in, std::int64_t local) {
                    const int q = quadratic_index[in.term];
                    const std::int64_t first = layout[in.term].hessian_begin(in.element);
                    if (q < 0) {
                        entry_source_[c.cursor[k]++] = hessian_offset_[in.term] + first + local;
                    } else {
                        c.quadratic_value[q * length + k] +=
                            quadratic_hessians[q][std::size_t(first + local)];
                        c.quadratic_touched[q * length + k] = 1;
                    }
                });
                for (std::size_t q = 0; q < num_quadratic; ++q) {
                    std::int64_t out = quadratic_begin[q][j];
                    for (std::size_t k = 0; k < length; ++k) {
                        if (!c.quadratic_touched[q * length + k]) continue;
                        quadratic_parts_[q].position[out] = begin + std::int64_t(k);
                        quadratic_parts_[q].value[out] = c.quadratic_value[q * length + k];
                        ++out;
                    }
                }
            }
        });
    std::fill(hessian_.valuePtr(), hessian_.valuePtr() + nnz, 0.0);
    diagonal_position_.assign(column_begin.begin(), column_begin.end() - 1);
    gradient_.setZero(nf);
}

bool HessianAssembler::matches(const Problem& problem) const {
    return problem.id() == problem_id_ && problem.structure_version() == structure_version_;
}

HessianAssembler::Evaluation HessianAssembler::evaluate(const Problem& problem,
                                                        const Eigen::VectorXd& x,
                                                        ProjectionMode mode, double epsilon,
                                                        PhaseTimes& times) {
    Evaluation result;
    const int num_terms = problem.num_terms();
    result.term_values.assign(num_terms, 0.0);
    Stopwatch watch;

    for (TermId t = 0; t < num_terms; ++t) {
        const Term& term = problem.term(t);
        const double w = term.weight();
        const double v = term.evaluate(
            x, w, gradient_slots_.data() + gradient_offset_[t],
            term.is_quadratic() ? nullptr : hessian_slots_.data() + hessian_offset_[t]);
        result.term_values[t] = v;
        if (!(std::abs(v) < kInfinity)) {  // +inf: infeasible; NaN: broken evaluation
            result.energy = v;
            times.evaluate += watch.lap();
            return result;
        }
        result.energy += w * v;
    }
    times.evaluate += watch.lap();

    for (TermId t = 0; t < num_terms; ++t) {
        if (hessian_offset_[t] < 0 || problem.term(t).is_convex()) continue;
        result.projected_blocks +=
            problem.term(t).project(x, hessian_slots_.data() + hessian_offset_[t], mode, epsilon);
    }
    times.project += watch.lap();

    double* values = hessian_.valuePtr();
    const std::int64_t nnz = hessian_.nonZeros();
    tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, nnz, 4096),
                      [&](const tbb::blocked_range<std::int64_t>& range) {
                          for (std::int64_t p = range.begin(); p != range.end(); ++p) {
                              double sum = 0.0;
                              for (std::int64_t s = entry_source_begin_[p];
                                   s < entry_source_begin_[p + 1]; ++s) {
                                  sum += hessian_slots_[entry_source_[s]];
                              }
                              values[p] = sum;
                          }
                      });
    for (const QuadraticPart& part : quadratic_parts_) {
        const double w = problem.term(part.term).weight();
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, part.position.size(), 4096),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                              for (std::size_t i = range.begin(); i != range.end(); ++i) {
                                  values[part.position[i]] += w * part.value[i];
                              }
                          });
    }
    tbb::parallel_for(tbb::blocked_range<Index>(0, num_free(), 4096),
                      [&](const tbb::blocked_range<Index>& range) {
                          for (Index j = range.begin(); j != range.end(); ++j) {
                              double sum = 0.0;
                              for (std::int64_t s = gradient_source_begin_[j];
                                   s < gradient_source_begin_[j + 1]; ++s) {
                                  sum += gradient_slots_[gradient_source_[s]];
                              }
                              gradient_[j] = sum;
                          }
                      });
    times.assemble += watch.lap();
    return result;
}

}  // namespace sa
