#pragma once
// The `sa` command's heap, mapped a growth at a time (jemalloc only; runtime_settings.cpp sets
// the allocator options this relies on: one arena, no separate arena for large allocations).
//
// jemalloc grows its heap by mappings of 2, 2.5, 3, 3.5 MB, ... that are not aligned to 2 MB, so
// that despite thp:always most of a small problem's heap is 4 KB pages, and each first touch of
// one is a page fault: about 11 us on the virtual machines this project is measured on, where
// tlc/param2d took 1,130 of them. Each growth of arena 0 is instead mapped in one
// madvise(MADV_POPULATE_WRITE) call when jemalloc maps it (optim/prefault.h): param2d
// --until-valid 500 page faults, 0.111 -> 0.104 s; 462 once large allocations went through
// arena 0 as well (BENCHMARKS.md).
//
// Costs: the unused tail of the last growth is resident too (at most kLargestPopulatedGrowth;
// jemalloc keeps it retained, and decay never returns it); jemalloc zeroes recycled memory by
// memset rather than by purging, as with any non-default extent hooks.

#include <cstddef>

namespace sa::cli {

/// Growths larger than this (64 MB), which only large problems make and which are mostly huge
/// pages, fault in as they are touched.
inline constexpr std::size_t kLargestPopulatedGrowth = std::size_t(64) << 20;

/// Installs the populating extent hooks on jemalloc's arena 0. Returns false (and changes
/// nothing) when jemalloc refuses, e.g. when the program's allocator is not jemalloc.
bool populate_heap_growth();

}  // namespace sa::cli
