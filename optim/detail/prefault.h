#pragma once
// Batched first touches of fresh memory.
//
// On the virtual machines this project is measured on, the first write to a fresh 4 KB page is a
// trap to the hypervisor; mapping a fresh buffer's pages in one madvise(MADV_POPULATE_WRITE) call
// (Linux 5.14+) was several times faster than faulting them in one by one (docs/measurements.md,
// "Figures moved out of the code"). The Hessian assembler allocates its per-entry tables once per
// problem and fills them at once, so it maps them this way. Only the buffers the call is given:
// nothing process-wide.

#include <cstddef>
#include <vector>

namespace sa {

/// Ranges smaller than this are left to ordinary page faults.
inline constexpr std::size_t kPrefaultBytes = std::size_t(64) << 10;

/// Maps the whole pages inside [data, data + bytes) now, in one system call. Does nothing for
/// ranges under kPrefaultBytes or where the kernel does not support it.
void prefault(void* data, std::size_t bytes);

/// v = n copies of `value`; when that needs a new, large buffer, its pages are mapped first.
template <class T>
void assign_prefaulted(std::vector<T>& v, std::size_t n, const T& value) {
    if (n > v.capacity() && n * sizeof(T) >= kPrefaultBytes) {
        std::vector<T> fresh;
        fresh.reserve(n);
        prefault(fresh.data(), n * sizeof(T));
        v.swap(fresh);
    }
    v.assign(n, value);
}

}  // namespace sa
