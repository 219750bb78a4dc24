#!/usr/bin/env bash
# Configures and builds the test build in build-asan/ (SA_SANITIZER_BUILD): clang 14,
# -fsanitize=address,undefined on every target (SA_SANITIZE; UBSan's per-access checks are left
# to AddressSanitizer, CMakeLists.txt says which), libFuzzer coverage of the file
# readers and the fuzz targets (SA_FUZZ), -O2 with line tables and assertions on (Eigen's index
# checks included). The sa command there links the shared libraries and uses the sanitizer's
# allocator. Arguments are build targets (default: all). Used by run-tests.sh and
# run-fuzzers.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SA_SANITIZER_BUILD:-build-asan}
if [[ ! -f "$build/build.ninja" ]]; then
    cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1" \
        -DCMAKE_CXX_COMPILER=clang++-14 -DSA_SANITIZE=ON -DSA_FUZZ=ON \
        -DSA_BUILD_BENCHMARKS=OFF ${SA_CMAKE_ARGS:-}
fi
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$build" --parallel "${SA_BUILD_JOBS:-$(nproc)}" "${targets[@]}"
