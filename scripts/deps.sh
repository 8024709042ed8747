#!/usr/bin/env bash
# Installs the Debian 12 packages the build, the tests and the benchmarks need, if any is missing.
set -euo pipefail
PKGS="build-essential cmake ninja-build pkg-config libcmocka-dev libinih-dev clang llvm libclang-rt-14-dev \
      gcc-arm-none-eabi libnewlib-arm-none-eabi binutils-arm-none-eabi qemu-system-arm \
      gcc-riscv64-unknown-elf picolibc-riscv64-unknown-elf qemu-system-misc valgrind graphviz \
      libosmesa6-dev libpng-dev ffmpeg"
missing=""
for p in $PKGS; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "installing:$missing"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq $missing >/dev/null
fi
