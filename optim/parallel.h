#pragma once
// Thread control. The Newton solver runs its parallel loops in a TBB arena of
// NewtonOptions::num_threads workers. The BLAS that CHOLMOD's supernodal factorization calls
// (OpenBLAS on Debian) has its own, process-wide, thread pool: programs that compare thread
// counts set it with set_blas_threads().

namespace sa {

/// The number of threads TBB uses by default on this machine.
int default_thread_count();

/// Sets OpenBLAS's thread count when the loaded BLAS is OpenBLAS; returns false otherwise
/// (another BLAS is loaded and keeps its own setting).
bool set_blas_threads(int threads);

}  // namespace sa
