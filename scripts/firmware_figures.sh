#!/usr/bin/env bash
# firmware_figures.sh [HOST_BUILD_DIR] - the firmware figures of docs/firmware.md: the runtime's code size on
# Cortex-M0+ at -Os (target: at most 2 KiB), the RAM of a 202-connection champion, and instructions per
# network step and per game step counted under QEMU -icount (not cycles: QEMU is not cycle-accurate).
# Needs a host build (default build/, for duel_bench and duel_evolve), arm-none-eabi-gcc and
# qemu-system-arm; RISC-V too when riscv64-unknown-elf-gcc and qemu-system-riscv32 are installed.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
host=$(realpath "${1:-$root/build}")
fw=$root/examples/firmware/fw.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for t in arm-none-eabi-gcc arm-none-eabi-size qemu-system-arm; do
  command -v "$t" > /dev/null || { echo "firmware_figures.sh: $t not installed (scripts/deps.sh): skipped"; exit 77; }
done
for t in duel_bench duel_evolve; do
  [ -x "$host/bin/$t" ] || { echo "firmware_figures.sh: $host/bin/$t missing: build the host first"; exit 1; }
done
"$host/bin/duel_bench" --write-blobs "$work"
a=$work/net39a.blob b=$work/net202a.blob

echo "== the runtime on Cortex-M0+ (arm-none-eabi-gcc $(arm-none-eabi-gcc -dumpversion) -mcpu=cortex-m0plus -mthumb -Os)"
FW_CPU=cortex-m0plus "$fw" build microbit "$work/m0plus" "$host/bin/duel_evolve" "$a" "$b"
arm-none-eabi-size -t "$work/m0plus/lib/libnrt.a" | sed 's| (ex .*||'
full=$(arm-none-eabi-size -t "$work/m0plus/lib/libnrt.a" | awk '/TOTALS/ {print $1 + $2}')
# the same sources built sync-only (NRT_NO_PROPAGATE, docs/runtime.md): the runtime of a firmware whose
# champions are all sync, where the 2 KiB target of issue 3 applies
sync=0
for f in nrt_load nrt_step nrt_sigmoid; do
  arm-none-eabi-gcc -mcpu=cortex-m0plus -mthumb -mfloat-abi=soft -ffreestanding -ffunction-sections -fdata-sections \
    -Os -std=c99 -DNRT_NO_STRERROR -DNRT_NO_PROPAGATE -I"$root/runtime/include" -I"$root/runtime/src" \
    -c "$root/runtime/src/$f.c" -o "$work/sync-$f.o"
  n=$(arm-none-eabi-size "$work/sync-$f.o" | awk 'NR == 2 {print $1 + $2}')
  echo "sync-only $f.c: $n bytes"
  sync=$((sync + n))
done
code=$sync
echo "runtime code (text + data): $full bytes with both step modes, $sync sync-only (NRT_NO_PROPAGATE); target at most 2048 (sync-only): $([ "$code" -le 2048 ] && echo met || echo NOT MET)"
# what the libraries need from outside (libgcc's helpers aside): memcpy and memset at most
needs() { # needs NM LIB
  "$1" -u "$2" | awk '$1 == "U" {print $2}' | { grep -v '^nrt_\|^duel_\|^__' || true; } | sort -u | tr '\n' ' '
}
echo "the runtime needs from a C library: $(needs arm-none-eabi-nm "$work/m0plus/lib/libnrt.a")"
echo "duelsim needs from a C library: $(needs arm-none-eabi-nm "$work/m0plus/lib/libduelsim.a")"
echo "duelsim:"
arm-none-eabi-size -t "$work/m0plus/lib/libduelsim.a" | sed 's| (ex .*||' | tail -n +2
echo "whole images (startup, semihosting, memcpy/memset, libgcc helpers, the two champions):"
arm-none-eabi-size "$work/m0plus/fw/duels.elf" "$work/m0plus/fw/figures.elf" | sed "s|$work/m0plus/fw/||"

measure() { # measure MACHINE BUILD_DIR
  "$fw" run "$1" "$2/fw/figures.elf" "$work/$1.txt" --icount
  cat "$work/$1.txt"
  # the games image of that build (text + data in flash, bss in RAM)
  local size=arm-none-eabi-size
  [ "$1" != sifive_e ] || size=riscv64-unknown-elf-size
  "$size" "$2/fw/duels.elf" | awk 'NR == 2 { print "games image: " $1 + $2 " bytes of flash, " $3 " of bss" }'
  echo "  (QEMU: $("$fw" command "$1" figures.elf OUT --icount))"
}

echo
echo "== instructions under QEMU -icount shift=0 (one virtual ns per instruction; QEMU is not cycle-accurate)"
echo "-- Cortex-M0+ build on microbit (Cortex-M0: the same Armv6-M instructions)"
measure microbit "$work/m0plus"
echo "-- Cortex-M3 on mps2-an385"
"$fw" build mps2-an385 "$work/m3" "$host/bin/duel_evolve" "$a" "$b"
measure mps2-an385 "$work/m3"
if command -v riscv64-unknown-elf-gcc > /dev/null && command -v qemu-system-riscv32 > /dev/null; then
  echo "-- rv32imac on sifive_e"
  "$fw" build sifive_e "$work/rv" "$host/bin/duel_evolve" "$a" "$b"
  measure sifive_e "$work/rv"
else
  echo "-- rv32imac: riscv64-unknown-elf-gcc or qemu-system-riscv32 not installed"
fi
[ "$code" -le 2048 ]
