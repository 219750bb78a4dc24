#include "frontends/cli/serial_openmp.h"

#include <atomic>

namespace sa::cli {
namespace {

std::atomic<long> serial_regions{0};

}  // namespace

long serial_openmp_regions() {
    return serial_regions.load(std::memory_order_relaxed);
}

}  // namespace sa::cli

/// The entry point of `#pragma omp parallel` in GCC's OpenMP ABI (libgomp's GOMP_4.0 version): the
/// region's body, once, on the calling thread.
extern "C" void GOMP_parallel(void (*fn)(void*), void* data, unsigned /*num_threads*/,
                              unsigned /*flags*/) {
    sa::cli::serial_regions.fetch_add(1, std::memory_order_relaxed);
    fn(data);
}
