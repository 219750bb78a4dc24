#pragma once
// Runs the OpenMP parallel regions of the libraries the solver calls (CHOLMOD) on the calling
// thread, without the OpenMP runtime.
//
// Why: CHOLMOD 3.0 (Debian 12) opens an OpenMP parallel region for every supernode, with a
// compiled-in 4 threads. libgomp starts a team for each region and wakes it through a futex
// system call even when it runs one thread, and system calls are slow on these virtual machines.
// Measured per supernodal factorization, one OpenBLAS thread, 2 cores: tlc/param2d's r-SA system
// (8,090 unknowns, 2.1e7 flops) 7.3-9.1 ms through libgomp (its threads sized dynamically), 3.7-4.5
// ms here; a 2,937-unknown 3D submesh 4.2 -> 2.9 ms; tlc/stgc-3d's full system (16,845 unknowns)
// 37 -> 27 ms; botijo's vertex stage (43,419 unknowns, 3.6e9 flops) 323-327 ms against 304-370
// ms: CHOLMOD's own threads never paid on 2 cores. The toolkit's parallelism is TBB's, over
// elements and submeshes, and a serial factorization does not compete with it.
//
// How: this file defines GOMP_parallel, the entry point GCC's code calls for `#pragma omp
// parallel`. Executables link it in with the linear solver, and the dynamic linker looks in the
// executable before libgomp, so libcholmod's calls land here (the linker exports the definition
// because libcholmod, on the link line, imports it). Inside a SerialOpenMP scope, on that thread,
// the region's body runs once on the calling thread, exactly as for a team of one:
// omp_get_thread_num() is 0 and omp_get_num_threads() 1 outside a team, and CHOLMOD 3.0 imports no
// other GOMP entry point (`nm -D libcholmod.so.3`: no barrier, no loop scheduling). Outside any
// scope, and on every other thread, the call goes on to libgomp's GOMP_parallel.

namespace sa {

/// While an instance lives, OpenMP parallel regions opened on this thread run serially (see
/// above). Scopes nest.
class SerialOpenMP {
  public:
    SerialOpenMP();
    ~SerialOpenMP();
    SerialOpenMP(const SerialOpenMP&) = delete;
    SerialOpenMP& operator=(const SerialOpenMP&) = delete;
};

/// Parallel regions run serially since the process started, on all threads.
long serial_openmp_regions();

}  // namespace sa
