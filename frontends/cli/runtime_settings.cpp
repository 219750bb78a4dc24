#include "frontends/cli/runtime_settings.h"

#include <dlfcn.h>

#include <cstdlib>
#include <cstring>
#include <new>

// jemalloc, the allocator the command links, reads `malloc_conf` when it starts, before main
// (MALLOC_CONF in the environment can still override it).
//
// thp:always asks the kernel for 2 MB transparent huge pages for the heap. On the 2-core machines
// this project is measured on, a first touch of a 4 KB page costs about 11 us (a 64 MB memset:
// 189 ms the first time, 3.6 ms the second), so that a small problem spent a third of its time in
// page faults: tlc/stgc-3d took 3,600 faults and 0.117 s with glibc's malloc, 1,700 and 0.078 s
// with these settings; tlc/cube 0.051 -> 0.042 s (perf stat -r 8, docs/measurements.md).
//
// narenas:1 and oversize_threshold:0: every thread and every size allocates from arena 0 (each
// further arena would also map its own metadata: eight arenas took `sa --help` from 14 to 29 MB).
// The hot loops do not allocate; botijo's default run took the same time with one arena as with
// jemalloc's eight. (A hook that mapped each growth of that arena populated was measured and
// dropped: docs/measurements.md, "What the sa command does to its own process".)
#ifndef SA_SYSTEM_ALLOCATOR
extern "C" {
// NOLINTNEXTLINE: the name and type are jemalloc's interface.
const char* malloc_conf = "thp:always,metadata_thp:always,narenas:1,oversize_threshold:0";
}
#endif

namespace sa::cli {
namespace {

bool blas_threads_set_here = false;

// Runs before OpenBLAS's own initialization when OpenBLAS is linked statically (a constructor of
// priority 101 comes before those without one), which then starts no worker thread. A worker
// allocates its 128 MB buffer as it starts, and OpenBLAS retries a failed allocation forever:
// under `ulimit -v` below about 190 MB every command, `sa --version` included, hung at 100% CPU
// while main waited to join that thread; at 50 MB creating the thread failed and OpenBLAS ended
// the process. The variable is removed again in main (apply_runtime_settings), so that programs
// the command starts see the environment they were given.
__attribute__((constructor(101))) void one_blas_thread() {
    if (std::getenv("OPENBLAS_NUM_THREADS") != nullptr) return;
    blas_threads_set_here = setenv("OPENBLAS_NUM_THREADS", "1", 0) == 0;
}

/// OpenBLAS (Debian 12's 0.3.21, built for every x86-64 core) picks its kernels from the CPU's
/// model number, and takes the SSE3 ones ("Prescott") for a model it does not know, even when the
/// CPU has AVX2 or AVX-512: on a VM reporting an "Intel(R) Xeon(R) Processor" of family 6, model
/// 207, large factorizations were much slower with them than with its AVX2 or AVX-512 ones
/// (figures: docs/measurements.md, PolyCube). Then the kernels the CPU's features allow are chosen
/// instead, as OPENBLAS_CORETYPE would have at start: SkylakeX (AVX-512 F, BW, DQ, VL) or Haswell
/// (AVX2, FMA). Nothing when OPENBLAS_CORETYPE is set, or OpenBLAS is not the BLAS.
void blas_kernels_for_this_cpu() {
    if (std::getenv("OPENBLAS_CORETYPE") != nullptr) return;
    const char* kernels = nullptr;
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
        __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl")) {
        kernels = "SkylakeX";
    } else if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
        kernels = "Haswell";
    } else {
        return;
    }
    using CoreName = char* (*)();
    using Init = void (*)();
    auto core = reinterpret_cast<CoreName>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
    auto quit = reinterpret_cast<Init>(dlsym(RTLD_DEFAULT, "gotoblas_dynamic_quit"));
    auto init = reinterpret_cast<Init>(dlsym(RTLD_DEFAULT, "gotoblas_dynamic_init"));
    if (core == nullptr || quit == nullptr || init == nullptr) return;
    const char* name = core();
    if (name == nullptr || std::strcmp(name, "Prescott") != 0) return;
    // gotoblas_dynamic_init() reads OPENBLAS_CORETYPE as at start; nothing has used the BLAS yet.
    if (setenv("OPENBLAS_CORETYPE", kernels, 1) != 0) return;
    quit();
    init();
    unsetenv("OPENBLAS_CORETYPE");
}

}  // namespace

void apply_runtime_settings() {
    blas_kernels_for_this_cpu();
    if (blas_threads_set_here) unsetenv("OPENBLAS_NUM_THREADS");
    // A shared OpenBLAS started before that constructor ran: one thread, as below, all the same.
    if (!blas_threads_set_here && std::getenv("OPENBLAS_NUM_THREADS") != nullptr) return;
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
