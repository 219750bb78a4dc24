#!/usr/bin/env bash
# Sets up, builds and runs the main job on a built-in example: the README's first command.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
build/bin/bend_bar_2d
