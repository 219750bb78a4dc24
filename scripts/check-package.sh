#!/usr/bin/env bash
# Checks the command and the package as users get them, CI's second phase (.ci/run): sets up,
# builds the Release build of the sa command and what it loads in build/ (the demo's build,
# build.sh sa), runs the tests of what the command does to its own process on it (its OpenMP
# regions through its own GOMP_parallel, libgomp's entry point, which needs gcc's build; memory
# limits, plugins, OpenBLAS's kernels), then installs the package and builds a user's project
# against it, and builds the optimizer alone. The test suite itself runs in the test build
# (run-tests.sh); bench/quality_guard.py runs this build's sa on shared data.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh sa serial_openmp_tests command_process_tests
build/bin/serial_openmp_tests --gtest_brief=1
build/bin/command_process_tests --gtest_brief=1

# ---- The installed package: a user's project built against `cmake --install` ------------------
# Installs the build into a temporary prefix, then configures, builds and runs tests/consumer/
# against it, outside the main build tree, and checks that no installed library or consumer
# program defines libgomp's symbols (only the sa command may change its own process).
check_installed_package() {
    local work prefix start milliseconds
    work=$(mktemp -d)
    prefix="$work/prefix"
    cmake --install build --prefix "$prefix" >/dev/null
    start=$(date +%s%N)
    cmake -S tests/consumer -B "$work/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
    milliseconds=$((($(date +%s%N) - start) / 1000000))
    echo "installed package: the consumer configured in ${milliseconds} ms"
    cmake --build "$work/consumer" --parallel "$(nproc)"
    ctest --test-dir "$work/consumer" --output-on-failure
    bash scripts/check-no-gomp.sh "$prefix/lib" "$work/consumer"
    rm -rf "$work"
}
check_installed_package

# ---- The optimizer alone: only Eigen, TBB and CHOLMOD ------------------------------------------
# Configures with geometry and the front-ends off and every other dependency made unfindable (the
# configure fails should the optimizer's layers come to need one), builds sa::optim and
# sa::energies as shared libraries, installs them and builds and runs the consumer's optimizer
# program against them.
check_optim_alone() {
    local work
    work=$(mktemp -d)
    cmake -S . -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release --no-warn-unused-cli \
        -DBUILD_SHARED_LIBS=ON -DSA_BUILD_GEOMETRY=OFF -DSA_BUILD_FRONTENDS=OFF \
        -DSA_BUILD_TESTS=OFF -DSA_BUILD_EXAMPLES=OFF -DSA_BUILD_BENCHMARKS=OFF \
        -DCMAKE_DISABLE_FIND_PACKAGE_OpenMesh=ON -DCMAKE_DISABLE_FIND_PACKAGE_VTK=ON \
        -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON \
        -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=ON -DCMAKE_DISABLE_FIND_PACKAGE_X11=ON \
        -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON \
        -DCMAKE_DISABLE_FIND_PACKAGE_OpenMP=ON >/dev/null
    cmake --build "$work/build" --parallel "$(nproc)"
    cmake --install "$work/build" --prefix "$work/prefix" >/dev/null
    cmake -S tests/consumer -B "$work/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
    cmake --build "$work/consumer" --parallel "$(nproc)"
    ctest --test-dir "$work/consumer" --output-on-failure
    bash scripts/check-no-gomp.sh "$work/prefix/lib"
    echo "optimizer alone: configured, built and used with Eigen, TBB and CHOLMOD only"
    rm -rf "$work"
}
check_optim_alone
