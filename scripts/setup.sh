#!/usr/bin/env bash
# Installs what is missing on Debian 12 (as root), builds, and runs the main job: a small coevolution (configs/quick.ini).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
ninja -C build
# The main job: configs/quick.ini into runs/quick (a second call resumes or, when
# the run is complete, just reports), then its dominant strategies against the
# built-in ones.
out=${1:-runs/quick}
if [ -e "$out/checkpoint.bin" ]; then
  ./build/bin/duel_evolve resume "$out"
else
  ./build/bin/duel_evolve run --config configs/quick.ini --out "$out"
fi
./build/bin/duel_evolve ladder "$out"
