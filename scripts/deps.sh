#!/usr/bin/env bash
# Installs the Debian 12 packages the build, the tests and the benchmarks need, if any is missing.
set -euo pipefail
PKGS="build-essential cmake ninja-build pkg-config libcmocka-dev procps clang llvm libclang-rt-14-dev \
      gcc-arm-none-eabi libnewlib-arm-none-eabi binutils-arm-none-eabi qemu-system-arm \
      gcc-riscv64-unknown-elf picolibc-riscv64-unknown-elf qemu-system-misc valgrind graphviz \
      libosmesa6-dev libpng-dev ffmpeg liblcm-dev liblcm-bin liblcm-java libglib2.0-dev python3-matplotlib \
      openmpi-bin libopenmpi-dev"
# LCM's TCP hub (lcm.lcm.TCPService, the tests over tcpq://) runs on any Java runtime
command -v java > /dev/null 2>&1 || PKGS="$PKGS default-jre-headless"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
missing=""
for p in $PKGS; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "installing:$missing"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq $missing >/dev/null
fi
# The Python lcm package from PyPI, for the test that decodes a log in Python (tests/lcm/decode_log.py)
if ! python3 -c 'import lcm' 2> /dev/null; then
  if ! python3 -m pip --version > /dev/null 2>&1; then
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq python3-pip > /dev/null
  fi
  echo "installing: lcm==1.5.3 (PyPI)"
  user=""
  if [ "$(id -u)" -ne 0 ]; then user="--user"; fi
  PIP_BREAK_SYSTEM_PACKAGES=1 python3 -m pip install -q $user lcm==1.5.3
fi
