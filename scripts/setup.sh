#!/usr/bin/env bash
# Installs what is missing on Debian 12 (as root), builds, and runs the main job on a small default.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
ninja -C build
# The main job (until duel_evolve exists): a short XOR benchmark run.
./build/bin/neat_bench xor --runs 20 "$@"
