#include "frontends/cli/runtime_settings.h"

#include <dlfcn.h>
#include <jemalloc/jemalloc.h>
#include <sys/mman.h>

#include <cstddef>
#include <cstdio>
#include <cstdlib>

// jemalloc, the allocator the command links, reads `malloc_conf` when it starts, before main
// (MALLOC_CONF in the environment can still override it).
//
// thp:always asks the kernel for 2 MB transparent huge pages for the heap. On the 2-core machines
// this project is measured on, a first touch of a 4 KB page costs about 11 us (a 64 MB memset:
// 189 ms the first time, 3.6 ms the second), so that a small problem spent a third of its time in
// page faults: tlc/stgc-3d took 3,600 faults and 0.117 s with glibc's malloc, 1,700 and 0.078 s
// with these settings; tlc/cube 0.051 -> 0.042 s (perf stat -r 8, BENCHMARKS.md).
//
// narenas:1: every thread allocates from arena 0, the one whose growth populate_heap_growth()
// hooks (each further arena would also map its own metadata: eight arenas took `sa --help` from
// 14 to 29 MB). The hot loops do not allocate; botijo's default run took the same time with one
// arena as with jemalloc's eight.
extern "C" {
// NOLINTNEXTLINE: the name and type are jemalloc's interface.
const char* malloc_conf = "thp:always,metadata_thp:always,narenas:1";
}

namespace sa::cli {
namespace {

extent_hooks_t* jemalloc_hooks = nullptr;
extent_hooks_t populating_hooks;

/// Growths of the heap up to this size are populated when they are mapped; larger ones, which
/// only large problems make and which are mostly huge pages, fault in as they are touched. It
/// bounds the memory made resident that the program may never use.
constexpr std::size_t kLargestPopulatedGrowth = std::size_t(64) << 20;

void* allocate_populated(extent_hooks_t* /*hooks*/, void* address, std::size_t size,
                         std::size_t alignment, bool* zero, bool* commit, unsigned arena) {
    void* memory =
        jemalloc_hooks->alloc(jemalloc_hooks, address, size, alignment, zero, commit, arena);
    // Kernels before 5.14 do not know MADV_POPULATE_WRITE and refuse it: the pages then fault
    // in one by one, as without this hook.
    if (memory != nullptr && size <= kLargestPopulatedGrowth)
        madvise(memory, size, MADV_POPULATE_WRITE);
    return memory;
}

/// jemalloc grows its heap by mappings of 2, 2.5, 3, 3.5 MB, ... that are not aligned to 2 MB,
/// so that most of a small problem's heap is 4 KB pages despite thp:always, and each first touch
/// of one is a page fault (about 11 us on the virtual machines this project is measured on).
/// MADV_POPULATE_WRITE maps a whole growth in one system call instead. tlc/param2d
/// --until-valid: 1,130 -> 500 page faults, 0.111 -> 0.104 s (three alternating blocks of perf
/// stat -r 10 each); stgc-3d --until-valid 0.054 -> 0.049 s (BENCHMARKS.md).
void populate_heap_growth() {
    std::size_t length = sizeof(jemalloc_hooks);
    if (mallctl("arena.0.extent_hooks", &jemalloc_hooks, &length, nullptr, 0) != 0) return;
    populating_hooks = *jemalloc_hooks;
    populating_hooks.alloc = allocate_populated;
    unsigned arenas = 0;
    length = sizeof(arenas);
    if (mallctl("arenas.narenas", &arenas, &length, nullptr, 0) != 0) return;
    extent_hooks_t* hooks = &populating_hooks;
    for (unsigned i = 0; i < arenas; ++i) {
        char name[40];
        std::snprintf(name, sizeof name, "arena.%u.extent_hooks", i);
        mallctl(name, nullptr, nullptr, &hooks, sizeof(hooks));
    }
}

}  // namespace

void apply_runtime_settings() {
    populate_heap_growth();
    if (std::getenv("OPENBLAS_NUM_THREADS") != nullptr) return;
    // Looked up rather than called: with SA_STATIC_COMMAND off, the BLAS behind CHOLMOD is the
    // one Debian's alternatives choose, which need not be OpenBLAS.
    using SetThreads = void (*)(int);
    auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    if (set == nullptr) return;
    set(1);
    // OpenBLAS started its worker threads when it was loaded, before main. With one thread they
    // get no work, but each spins on sched_yield before it sleeps and competes with TBB's workers
    // for the cores. blas_thread_shutdown_ (OpenBLAS's own, for fork) joins them; a later
    // openblas_set_num_threads(n > 1) starts them again.
    using Shutdown = int (*)();
    if (auto shutdown = reinterpret_cast<Shutdown>(dlsym(RTLD_DEFAULT, "blas_thread_shutdown_")))
        shutdown();
}

}  // namespace sa::cli
