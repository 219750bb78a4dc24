#pragma once
// The one line the `sa` command prints when an allocation fails (exit status 4): what it was
// doing, the size of the request that failed when known, the memory it had, and the limit that
// stopped it, e.g.
//   out of memory while solving (Simplex Assembly on 57,259 tetrahedra): a request for 1.2 GB
//   failed; peak resident memory 0.38 GB; address-space limit (ulimit -v) 0.50 GB

#include <cstddef>
#include <string>

namespace sa::cli {

/// What the command is doing, named for a user ("reading --rest botijo.node"); main thread only.
void set_activity(std::string what);

/// Called with the size of a request that could not be had (by the heap's extent hook,
/// populated_heap.cpp, when jemalloc cannot map more memory).
void note_failed_allocation(std::size_t bytes) noexcept;

/// The message for a std::bad_alloc caught in main.
std::string out_of_memory_message();

/// The soft address-space or data-segment limit (ulimit -v, ulimit -d) in bytes, the smaller of
/// the two, or 0 when neither is set; `which` gets its name.
std::size_t memory_limit(std::string* which = nullptr);

}  // namespace sa::cli
