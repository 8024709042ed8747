#!/usr/bin/env bash
# fw.sh - the firmware example for one QEMU machine: build (runtime and duelsim for its core, then the images) and run (docs/firmware.md).
#   fw.sh build MACHINE DIR DUEL_EVOLVE A.blob B.blob [CORRUPT_OFFSET]
#       the runtime and duelsim, the documented NEAT_RUNTIME_ONLY build, in DIR/lib; the images
#       DIR/fw/duels.elf and DIR/fw/figures.elf with A and B exported by DUEL_EVOLVE; with
#       CORRUPT_OFFSET, duels.elf links B with that byte corrupted. FW_CPU overrides the core; FW_WORLD (a
#       world's name or an INI file with a [world] section) makes duels.elf play in that world.
#   fw.sh run MACHINE ELF OUT [--icount]
#       the image under QEMU (60 s limit), the semihosting output in OUT; exits with the
#       firmware's status (QEMU passes SYS_EXIT_EXTENDED's on), 124 on timeout.
#   fw.sh command MACHINE ELF OUT [--icount]
#       prints that QEMU command line.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
here=$root/examples/firmware

usage() {
  sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
  exit 2
}

machine() { # sets arch, cpu, qemu, toolchain for machine $1
  case "$1" in
  microbit) arch=arm cpu=cortex-m0 qemu=qemu-system-arm ;;             # nRF51822, 16 KiB RAM
  mps2-an385 | lm3s6965evb) arch=arm cpu=cortex-m3 qemu=qemu-system-arm ;;
  mps2-an386) arch=arm cpu=cortex-m4f qemu=qemu-system-arm ;;          # Cortex-M4 with FPU
  sifive_e) arch=riscv cpu=rv32imac qemu=qemu-system-riscv32 ;;        # E31, 16 KiB DTIM
  *) echo "fw.sh: unknown machine '$1' (microbit, mps2-an385, mps2-an386, lm3s6965evb, sifive_e)" >&2; exit 2 ;;
  esac
  cpu=${FW_CPU:-$cpu}
  if [ "$arch" = arm ]; then
    toolchain=(-DCMAKE_TOOLCHAIN_FILE="$root/cmake/arm-none-eabi.cmake" -DNEAT_ARM_CPU="$cpu")
  else
    toolchain=(-DCMAKE_TOOLCHAIN_FILE="$root/cmake/riscv64-unknown-elf.cmake" -DNEAT_RISCV_ARCH="$cpu")
  fi
}

qemu_command() { # qemu_command MACHINE ELF OUT [--icount]: sets cmd
  machine "$1"
  cmd=("$qemu" -M "$1" -display none -monitor none -serial null
       -chardev "file,id=semihosting,path=$3" -semihosting-config "enable=on,target=native,chardev=semihosting")
  if [ "${4:-}" = --icount ]; then cmd+=(-icount shift=0); fi
  cmd+=(-kernel "$2")
}

# runs "$@" quietly; on failure shows its output and fails
quiet() {
  local log
  log=$(mktemp)
  if ! "$@" > "$log" 2>&1; then
    cat "$log" >&2
    rm -f "$log"
    echo "fw.sh: failed: $*" >&2
    exit 1
  fi
  rm -f "$log"
}

case "${1:-}" in
build)
  [ $# -ge 6 ] || usage
  mach=$2 dir=$3 duel=$4 a=$5 b=$6 corrupt=${7:-}
  machine "$mach"
  mkdir -p "$dir"
  dir=$(cd "$dir" && pwd)
  quiet cmake -S "$root" -B "$dir/lib" -G Ninja "${toolchain[@]}" -DCMAKE_BUILD_TYPE=MinSizeRel -DNEAT_RUNTIME_ONLY=ON
  quiet ninja -C "$dir/lib"
  quiet cmake -S "$here" -B "$dir/fw" -G Ninja "${toolchain[@]}" -DCMAKE_BUILD_TYPE=MinSizeRel \
    -DFW_MACHINE="$mach" -DNEAT_LIB_DIR="$dir/lib" -DNEAT_DUEL_EVOLVE="$(realpath "$duel")" \
    -DFW_CHAMPION_A="$(realpath "$a")" -DFW_CHAMPION_B="$(realpath "$b")" -DFW_CORRUPT_B="$corrupt" \
    -DFW_WORLD="${FW_WORLD:-}"
  quiet ninja -C "$dir/fw"
  ;;
run)
  [ $# -ge 4 ] || usage
  qemu_command "$2" "$3" "$4" "${5:-}"
  rm -f "$4"
  rc=0
  timeout 60 "${cmd[@]}" || rc=$?
  exit $rc
  ;;
command)
  [ $# -ge 4 ] || usage
  qemu_command "$2" "$3" "$4" "${5:-}"
  echo "${cmd[*]}"
  ;;
*)
  usage
  ;;
esac
