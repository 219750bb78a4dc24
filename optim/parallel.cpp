#include "optim/parallel.h"

#include <dlfcn.h>
#include <tbb/info.h>

namespace sa {

int default_thread_count() {
    return tbb::info::default_concurrency();
}

bool set_blas_threads(int threads) {
    // Looked up at run time so that the library links against any BLAS.
    using SetThreads = void (*)(int);
    auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    if (set == nullptr) return false;
    set(threads);
    return true;
}

}  // namespace sa
