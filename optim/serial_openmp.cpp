#include "optim/serial_openmp.h"

#include <dlfcn.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace sa {
namespace {

thread_local int serial_depth = 0;
std::atomic<long> serial_regions{0};

using GompParallel = void (*)(void (*)(void*), void*, unsigned, unsigned);

/// libgomp's GOMP_parallel, the definition after ours in the lookup order.
GompParallel runtime_parallel() {
    static const GompParallel next = [] {
        void* symbol = dlvsym(RTLD_NEXT, "GOMP_parallel", "GOMP_4.0");
        if (symbol == nullptr) symbol = dlsym(RTLD_NEXT, "GOMP_parallel");
        return reinterpret_cast<GompParallel>(symbol);
    }();
    return next;
}

}  // namespace

SerialOpenMP::SerialOpenMP() {
    ++serial_depth;
}
SerialOpenMP::~SerialOpenMP() {
    --serial_depth;
}

long serial_openmp_regions() {
    return serial_regions.load(std::memory_order_relaxed);
}

}  // namespace sa

/// The entry point of `#pragma omp parallel` in GCC's OpenMP ABI (libgomp's GOMP_4.0 version).
extern "C" void GOMP_parallel(void (*fn)(void*), void* data, unsigned num_threads, unsigned flags) {
    if (sa::serial_depth > 0) {
        sa::serial_regions.fetch_add(1, std::memory_order_relaxed);
        fn(data);
        return;
    }
    const sa::GompParallel next = sa::runtime_parallel();
    if (next == nullptr) {
        // Unreachable for code compiled with -fopenmp: it links libgomp, which defines it.
        std::fputs("sa: GOMP_parallel called without an OpenMP runtime loaded\n", stderr);
        std::abort();
    }
    next(fn, data, num_threads, flags);
}
