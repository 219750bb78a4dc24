#!/usr/bin/env bash
# Configures and builds the project in build/ (Release, Ninja). Executables land in build/bin/.
set -euo pipefail
cd "$(dirname "$0")/.."
build_type=${SA_BUILD_TYPE:-Release}
if [[ ! -f build/build.ninja ]]; then
    cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE="$build_type"
fi
cmake --build build --parallel "${SA_BUILD_JOBS:-$(nproc)}"
