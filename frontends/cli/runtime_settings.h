#pragma once
// Process-wide settings of the `sa` command (not of the libraries: programs built on them keep
// their own): the allocator's, read by jemalloc before main, and the BLAS's, applied by
// apply_runtime_settings() at the start of main.

namespace sa::cli {

/// OpenBLAS's AVX-512 or AVX2 kernels when it fell back to its SSE3 ones on a CPU that has them
/// but whose model it does not know (runtime_settings.cpp), unless OPENBLAS_CORETYPE is set. And
/// one OpenBLAS thread, its idle workers joined, unless OPENBLAS_NUM_THREADS says otherwise (and
/// nothing when the BLAS is not OpenBLAS). Measured on CHOLMOD supernodal factorizations,
/// OpenBLAS's second thread never paid on these 2-core machines and its spinning (sched_yield)
/// slowed the small ones, two threads
/// -> one: tlc/param2d's Hessian 9.8 -> 7.9 ms, a 2,937-unknown stgc-3d submesh 5.1 -> 4.4 ms,
/// stgc-3d's full Hessian 56 -> 50 ms, botijo's vertex stage 215 -> 221 ms, a 1M-unknown grid
/// Laplacian 3.0 -> 2.75 s (all with the supernode relaxation of linear_solver.cpp).
void apply_runtime_settings();

/// Under a memory limit (ulimit -v or -d), has OpenBLAS take its work buffer now, or throws
/// std::bad_alloc (the request's size noted, out_of_memory.h) when it cannot be had: OpenBLAS
/// itself retries a failed allocation forever. Called once, by main, before any command that
/// solves runs (and so before it reads its input).
/// Nothing without a limit, or when the BLAS is not OpenBLAS.
void reserve_blas_buffer();

}  // namespace sa::cli
