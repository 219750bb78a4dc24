#!/usr/bin/env bash
# Configures and builds the project in build/ (Release, Ninja). Executables land in build/bin/.
# SA_CMAKE_ARGS adds configure arguments (on the first run), SA_BUILD_JOBS sets the parallel jobs.
# Arguments are build targets (default: all; run-demo.sh builds only `sa` and the plugins it
# loads).
set -euo pipefail
cd "$(dirname "$0")/.."
build_type=${SA_BUILD_TYPE:-Release}
if [[ ! -f build/build.ninja ]]; then
    cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE="$build_type" ${SA_CMAKE_ARGS:-}
fi
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build --parallel "${SA_BUILD_JOBS:-$(nproc)}" "${targets[@]}"
