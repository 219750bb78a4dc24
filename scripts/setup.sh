#!/usr/bin/env bash
# Installs every Debian 12 package the build, the tests and the benchmarks need.
# Idempotent: when everything is present it only checks (a second or two) and exits.
# Run as root (CI does); otherwise it uses sudo when that is available.
set -euo pipefail

packages=(
    g++ cmake ninja-build pkg-config python3
    libeigen3-dev
    libsuitesparse-dev libopenblas-dev
    libtbb-dev
    libopenmesh-dev
    libvtk9-dev
    libgtest-dev libgmock-dev libbenchmark-dev
    libcli11-dev nlohmann-json3-dev
    libjemalloc-dev
    libcairo2-dev
    libx11-dev xvfb xauth
    # The test build and the fuzz targets (run-tests.sh, run-fuzzers.sh): clang,
    # its sanitizer and libFuzzer runtimes, llvm-symbolizer for the reports' stack traces.
    clang-14 libclang-rt-14-dev llvm-14
)

missing=()
for p in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
    [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
    echo "setup: all ${#packages[@]} packages present"
    exit 0
fi

sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
    sudo_cmd=(sudo)
fi

echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
