#pragma once
// The sa command runs the OpenMP parallel regions of the libraries it calls on the calling thread,
// without the OpenMP runtime: a process-wide setting of the command, never of the libraries
// (programs built on them keep libgomp's behaviour, or set OMP_THREAD_LIMIT themselves).
//
// Why: CHOLMOD 3.0 (Debian 12), the only library here with OpenMP, opens a parallel region for
// every supernode with a compiled-in 4 threads. libgomp starts a team for each and wakes it
// through futex system calls, which are slow on these virtual machines, and CHOLMOD's threads
// never paid on 2 cores. The toolkit's parallelism is TBB's, over elements and submeshes.
// Measured gains on tlc/param2d, tlc/stgc-3d and deform/botijo are in docs/measurements.md ("What
// the sa command does to its own process").
//
// How: serial_openmp.cpp defines GOMP_parallel, the entry point GCC's code calls for `#pragma omp
// parallel`, and is linked into the command only. The dynamic linker looks in the executable
// before libgomp, so libcholmod's calls land there (the linker exports the definition because
// libcholmod imports it; with the static archives the reference binds at link time). The body of
// every region runs once on the calling thread, exactly as for a team of one: omp_get_thread_num()
// is 0 and omp_get_num_threads() 1 outside a team, and CHOLMOD 3.0 imports no other GOMP entry
// point (`nm -D libcholmod.so.3`: no barrier, no loop scheduling).

namespace sa::cli {

/// Parallel regions run serially since the process started, on all threads.
long serial_openmp_regions();

}  // namespace sa::cli
