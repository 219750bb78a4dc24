#pragma once
// The two reductions over a term's elements that EnergyTerm and DynamicEnergyTerm share: the sum
// of the element values (+inf as soon as one is) and the smallest feasible step. Both split
// [0, n) into ranges of `grain` elements; the sum is TBB's deterministic reduce, so that it
// gives the same bits on any number of threads. `make_scratch()` makes one task's working room,
// passed to every call of `value(e, scratch)` or `step(e, scratch)` in that task.

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>
#include <functional>

#include "optim/types.h"

namespace sa::detail {

/// Sum over e in [0, n) of value(e, scratch): +inf when one is +inf, NaN when one is NaN.
template <class MakeScratch, class Value>
double sum_of_element_values(Index n, Index grain, MakeScratch make_scratch, Value value) {
    std::atomic<bool> infeasible{false};
    const double sum = tbb::parallel_deterministic_reduce(
        tbb::blocked_range<Index>(0, n, grain), 0.0,
        [&](const tbb::blocked_range<Index>& r, double acc) {
            if (infeasible.load(std::memory_order_relaxed)) return kInfinity;
            auto scratch = make_scratch();
            for (Index e = r.begin(); e != r.end(); ++e) {
                const double v = value(e, scratch);
                if (!(v < kInfinity)) {
                    if (v == kInfinity) infeasible.store(true, std::memory_order_relaxed);
                    return v;
                }
                acc += v;
            }
            return acc;
        },
        std::plus<double>());
    return infeasible.load() ? kInfinity : sum;
}

/// The smallest step(e, scratch) over e in [0, n) (+inf when n is 0).
template <class MakeScratch, class Step>
double smallest_element_step(Index n, Index grain, MakeScratch make_scratch, Step step) {
    return tbb::parallel_reduce(
        tbb::blocked_range<Index>(0, n, grain), kInfinity,
        [&](const tbb::blocked_range<Index>& r, double smallest) {
            auto scratch = make_scratch();
            for (Index e = r.begin(); e != r.end(); ++e)
                smallest = std::min(smallest, double(step(e, scratch)));
            return smallest;
        },
        [](double a, double b) { return std::min(a, b); });
}

}  // namespace sa::detail
