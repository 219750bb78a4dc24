#include "frontends/cli/populated_heap.h"

#include <jemalloc/jemalloc.h>

#include "frontends/cli/out_of_memory.h"
#include "optim/prefault.h"

namespace sa::cli {
namespace {

extent_hooks_t* jemalloc_hooks = nullptr;  ///< jemalloc's own, which do the mapping
extent_hooks_t populating_hooks;

void* allocate_populated(extent_hooks_t* /*hooks*/, void* address, std::size_t size,
                         std::size_t alignment, bool* zero, bool* commit, unsigned arena) {
    void* memory =
        jemalloc_hooks->alloc(jemalloc_hooks, address, size, alignment, zero, commit, arena);
    if (memory != nullptr && *commit && size <= kLargestPopulatedGrowth) prefault(memory, size);
    // After a larger growth of its reserve fails, jemalloc asks for the request's own extent: the
    // last failure is the size an out-of-memory message reports.
    if (memory == nullptr) note_failed_allocation(size);
    return memory;
}

}  // namespace

bool populate_heap_growth() {
    std::size_t length = sizeof(jemalloc_hooks);
    if (mallctl("arena.0.extent_hooks", &jemalloc_hooks, &length, nullptr, 0) != 0) return false;
    populating_hooks = *jemalloc_hooks;
    populating_hooks.alloc = allocate_populated;
    // No dalloc: the extents are retained anyway (jemalloc's retain, the default on Linux), and
    // without the hook jemalloc knows it at once instead of calling one that refuses.
    populating_hooks.dalloc = nullptr;
    extent_hooks_t* hooks = &populating_hooks;
    return mallctl("arena.0.extent_hooks", nullptr, nullptr, &hooks, sizeof(hooks)) == 0;
}

}  // namespace sa::cli
