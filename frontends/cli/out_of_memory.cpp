#include "frontends/cli/out_of_memory.h"

#include <dlfcn.h>
#include <sys/resource.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>

#include "frontends/cli/cli_support.h"
#include "frontends/cli/runtime_settings.h"

namespace sa::cli {
namespace {

std::string& activity() {
    static std::string what = "starting";
    return what;
}

std::atomic<std::size_t> failed_request{0};

std::string gigabytes(double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f GB", bytes / (1024.0 * 1024.0 * 1024.0));
    return text;
}

}  // namespace

void set_activity(std::string what) {
    activity() = std::move(what);
}

void note_failed_allocation(std::size_t bytes) noexcept {
    failed_request.store(bytes, std::memory_order_relaxed);
}

std::size_t memory_limit(std::string* which) {
    std::size_t limit = 0;
    for (const auto& [resource, name] :
         {std::pair{RLIMIT_AS, "address-space limit (ulimit -v)"},
          std::pair{RLIMIT_DATA, "data-segment limit (ulimit -d)"}}) {
        rlimit value{};
        if (getrlimit(resource, &value) != 0 || value.rlim_cur == RLIM_INFINITY) continue;
        if (limit == 0 || value.rlim_cur < limit) {
            limit = static_cast<std::size_t>(value.rlim_cur);
            if (which != nullptr) *which = name;
        }
    }
    return limit;
}

std::string out_of_memory_message() {
    // Built without further large allocations: a few short strings.
    std::string message = "out of memory while " + activity();
    const std::size_t request = failed_request.load(std::memory_order_relaxed);
    message += request > 0 ? ": a request for " + gigabytes(double(request)) + " failed; "
                           : ": an allocation failed; ";
    message += "peak resident memory " + gigabytes(peak_memory_gb() * 1024.0 * 1024.0 * 1024.0);
    std::string which;
    const std::size_t limit = memory_limit(&which);
    if (limit > 0) message += "; " + which + " " + gigabytes(double(limit));
    return message;
}

namespace {

// OpenBLAS's work buffer: BUFFER_SIZE (32 << 22 bytes on x86-64) plus a page, requested with
// malloc() by its alloc_malloc() on the first BLAS call (seen in gdb: jemalloc maps 160 MB for it).
constexpr std::size_t kBlasBuffer = (std::size_t(32) << 22) + 4096;

}  // namespace

// Declared in runtime_settings.h and called by sa_main.cpp for every command that solves; here,
// beside the out-of-memory message it leads to.
void reserve_blas_buffer() {
    if (memory_limit() == 0) return;  // without a limit, malloc of address space does not fail
    using Allocate = void* (*)(int);
    using Release = void (*)(void*);
    auto allocate = reinterpret_cast<Allocate>(dlsym(RTLD_DEFAULT, "blas_memory_alloc"));
    auto release = reinterpret_cast<Release>(dlsym(RTLD_DEFAULT, "blas_memory_free"));
    if (allocate == nullptr || release == nullptr) return;  // not OpenBLAS
    set_activity("reserving OpenBLAS's 128 MB work buffer (for the sparse Cholesky factorization)");
    // OpenBLAS would retry forever: try first, and fail at once if it cannot be had.
    void* probe = std::malloc(kBlasBuffer);
    if (probe == nullptr) {
        note_failed_allocation(kBlasBuffer);
        throw std::bad_alloc();
    }
    std::free(probe);
    release(allocate(0));  // kept by OpenBLAS for its later calls
}

}  // namespace sa::cli
