#!/usr/bin/env bash
# qemu_identity.sh MACHINE|refused|world FW_SH DUEL_EVOLVE FW_HOST BLOBS WORK - the firmware example built for a QEMU machine prints, byte for byte, what its host twin prints; "refused": a corrupted champion linked into the image is refused with its error code, the same on both; "world": an image built for a world other than v1 (FW_WORLD) plays that world's games, as the host twin does. Exit 77 (skipped) without the cross compiler or QEMU.
set -euo pipefail
what=$1 fw=$2 duel=$3 host=$4 blobs=$5 work=$6
a=$blobs/champion.blob # evolved: 5 generations of tests/tools/coev-small.ini
b=$blobs/net202a.blob  # 202 connections, hidden nodes, recurrent connections

fail() { echo "FAIL: $*"; exit 1; }
need() {
  for t in "$@"; do
    command -v "$t" > /dev/null || { echo "skipped: $t not installed (scripts/deps.sh installs it)"; exit 77; }
  done
}

machine=$what
[ "$what" = refused ] || [ "$what" = world ] && machine=microbit
case "$machine" in
sifive_e) need riscv64-unknown-elf-gcc qemu-system-riscv32 ;;
*) need arm-none-eabi-gcc qemu-system-arm ;;
esac
mkdir -p "$work"

# same_output HOST_OUT TARGET_OUT
same_output() {
  if ! cmp -s "$1" "$2"; then
    diff "$1" "$2" | head -20
    fail "$machine prints something else than the host (above: < host, > target)"
  fi
}

if [ "$what" = world ]; then
  # every chosen rule other than v1's: starts, energies, food, eating, ranges
  cp "$(dirname "$0")/../../../tests/tools/fixtures/world-variant.ini" "$work/world.ini"
  "$duel" export --world "$work/world.ini" --raw -o "$work/world.bin"
  FW_WORLD="$work/world.ini" "$fw" build "$machine" "$work" "$duel" "$a" "$b"
  "$host" "$a" "$b" "$work/world.bin" > "$work/host.txt" || fail "host: exit $?"
  "$host" "$a" "$b" > "$work/host-v1.txt" || fail "host (v1): exit $?"
  rc=0
  "$fw" run "$machine" "$work/fw/duels.elf" "$work/target.txt" || rc=$?
  [ "$rc" -eq 0 ] || { cat "$work/target.txt"; fail "$machine: exit $rc (124: timeout)"; }
  same_output "$work/host.txt" "$work/target.txt"
  id=$("$duel" config --dump --config "$work/world.ini" | sed -n 's/.*(identity \([0-9a-f]*\)).*/\1/p')
  head -1 "$work/target.txt" | grep -q "world 0x${id:0:8}0x${id:8:8}" || fail "the image does not name the world $id"
  ! cmp -s <(tail -n +2 "$work/host.txt") <(tail -n +2 "$work/host-v1.txt") || fail "the world's games are v1's"
  echo "$machine in world $id: identical to the host: $(tail -1 "$work/target.txt")"
  exit 0
fi

if [ "$what" != refused ]; then
  [ "$("$duel" inspect "$b" | sed -n 's/^recurrent: \([0-9]*\).*/\1/p')" -gt 0 ] || fail "$b: no recurrent connection"
  "$fw" build "$machine" "$work" "$duel" "$a" "$b"
  rc=0
  "$host" "$a" "$b" > "$work/host.txt" || rc=$?
  [ "$rc" -eq 0 ] || fail "host: exit $rc"
  rc=0
  "$fw" run "$machine" "$work/fw/duels.elf" "$work/target.txt" || rc=$?
  [ "$rc" -eq 0 ] || { cat "$work/target.txt"; fail "$machine: exit $rc (124: timeout)"; }
  same_output "$work/host.txt" "$work/target.txt"
  out=$work/target.txt
  games=$(grep -c '^game ' "$out")
  [ "$games" -ge 20 ] || fail "only $games games"
  grep -q '^champion B: .* [1-9][0-9]* hidden, 202 connections' "$out" || fail "champion B is not the 202-connection net"
  for who in "west A" "east A" "west B" "east B"; do
    grep -q "^game .*: .*$who" "$out" || fail "no game with $who"
  done
  foods=$(sed -n 's/^game [0-9]* food \([a-z0-9]*\):.*/\1/p' "$out" | sort -u | wc -l)
  [ "$foods" -ge 4 ] || fail "only $foods food configurations"
  tail -1 "$out" | grep -q "^$games games: .*; all outputs 0x[0-9a-f]\{8\}$" || fail "no summary line"
  echo "$machine: $games games, identical to the host ($(wc -c < "$out") bytes): $(tail -1 "$out")"
  exit 0
fi

# refused: byte 4 (the format version) and byte 100 (a connection: the CRC no longer matches)
for case in "4 -4 NRT_E_VERSION" "100 -7 NRT_E_CRC"; do
  set -- $case
  offset=$1 code=$2 name=$3
  "$fw" build "$machine" "$work" "$duel" "$a" "$b" "$offset"
  # the host twin reads the same damage from a file
  cp "$b" "$work/bad.blob"
  byte=$(od -An -tu1 -j "$offset" -N1 "$b" | tr -d ' ')
  printf "\\$(printf %03o $((byte ^ 0x40)))" | dd of="$work/bad.blob" bs=1 seek="$offset" conv=notrunc status=none
  rc=0
  "$host" "$a" "$work/bad.blob" > "$work/host.txt" || rc=$?
  [ "$rc" -eq 2 ] || fail "host: exit $rc on the corrupted blob, expected 2"
  rc=0
  "$fw" run "$machine" "$work/fw/duels.elf" "$work/target.txt" || rc=$?
  [ "$rc" -eq 2 ] || { cat "$work/target.txt"; fail "$machine: exit $rc with a corrupted champion, expected 2"; }
  same_output "$work/host.txt" "$work/target.txt"
  last=$(tail -1 "$work/target.txt")
  [ "$last" = "champion B: refused by the runtime: error $code $name" ] || fail "last line: '$last'"
  ! grep -q '^game ' "$work/target.txt" || fail "games played with a refused champion"
  echo "byte $offset corrupted: $last (exit 2, the same on the host)"
done
