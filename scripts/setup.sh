#!/usr/bin/env bash
# Installs what is missing on Debian 12 (as root), builds, and runs the main job on a small default.
set -euo pipefail
cd "$(dirname "$0")/.."
PKGS="build-essential cmake ninja-build pkg-config libcmocka-dev libinih-dev clang llvm \
      gcc-arm-none-eabi libnewlib-arm-none-eabi valgrind"
missing=""
for p in $PKGS; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq $missing
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
ninja -C build
# The main job (until duel_evolve exists): a short XOR benchmark run.
./build/bin/neat_bench xor --runs 20 "$@"
