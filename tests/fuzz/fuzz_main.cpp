// A libFuzzer executable for one reader: SA_FUZZ_TARGET names it (fuzz_targets.h). An input that
// ends in sa::Error is a rejected input; any other exception escapes and libFuzzer reports it.
#include <cstddef>
#include <cstdint>

#include "fuzz_targets.h"
#include "optim/errors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const sa::fuzz::Target& target = sa::fuzz::target(SA_FUZZ_TARGET);
    try {
        target.run(data, size);
    } catch (const sa::Error&) {
        // A bad input, reported as such.
    }
    return 0;
}
