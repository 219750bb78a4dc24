#!/usr/bin/env bash
# Sets up, builds the sa command (and the plugins it loads, not the tests) and runs the main job
# on a built-in example: the README's first command.
# `sa demo` repairs a folded harmonic map of a square onto a star (the paper's Figure 1 in
# miniature) and writes its .vtu files to out/demo/ (replacing those of an earlier run).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh sa
build/bin/sa demo --out-dir out/demo --force
