#include "frontends/cli/out_of_memory.h"

#include <sys/resource.h>

#include <atomic>
#include <cstdio>

#include "frontends/cli/cli_support.h"

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

}  // namespace sa::cli
