#!/usr/bin/env bash
# duel_cli.sh - duel_evolve play from the outside: outcomes, the trace's columns and rows, and bad input (exit 2, one line).
set -euo pipefail
duel=$1
what=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=/dev/null
. "$(dirname "$0")/cli_lib.sh"

case "$what" in
bad-input)
  expect_bad "builtin:nope: unknown builtin" play builtin:nope builtin:idle
  expect_bad "missing.blob: cannot open" play "$tmp/missing.blob" builtin:idle
  printf 'NRTB this is not a blob at all, just text long enough' > "$tmp/bad.blob"
  expect_bad "bad.blob: not a valid champion blob" play "$tmp/bad.blob" builtin:idle
  expect_bad "bad food configuration '144'" play builtin:idle builtin:idle --food 144
  expect_bad "bad food configuration 'x'" play builtin:idle builtin:idle --food x
  expect_bad "--side takes west or east" play builtin:idle builtin:idle --side north
  expect_bad "unknown option" play builtin:idle builtin:idle --what 1
  ;;
trace)
  "$duel" play builtin:forager-hunter builtin:idle --trace "$tmp/t.csv" > "$tmp/out.txt"
  grep -q "west wins" "$tmp/out.txt" || { cat "$tmp/out.txt"; exit 1; }
  steps=$(sed -n 's/.* after \([0-9]*\) steps/\1/p' "$tmp/out.txt")
  head -1 "$tmp/t.csv" | tr ',' '\n' > "$tmp/cols"
  [ "$(wc -l < "$tmp/cols")" -eq 46 ] || { echo "expected 46 columns"; exit 1; }
  [ "$(sed -n 1p "$tmp/cols")" = t ] && [ "$(sed -n 2p "$tmp/cols")" = west_x ] &&
    [ "$(sed -n 41p "$tmp/cols")" = east_out2 ] && [ "$(sed -n 43p "$tmp/cols")" = event ] &&
    [ "$(sed -n '44,46p' "$tmp/cols" | tr '\n' ' ')" = "world_id west_step east_step " ] ||
    { echo "bad header"; exit 1; }
  # one row per step, t from 0, the last row's event is the collision
  [ "$(($(wc -l < "$tmp/t.csv") - 1))" -eq "$steps" ] || { echo "rows != $steps steps"; exit 1; }
  [ "$(sed -n 2p "$tmp/t.csv" | cut -d, -f1-5)" = "0,100.000000,300.000000,3.141593,1200.000000" ] ||
    { echo "bad first row: $(sed -n 2p "$tmp/t.csv" | cut -c1-80)"; exit 1; }
  # every row ends with the world (v1's identity) and how each side stepped (two built-in strategies)
  tail -1 "$tmp/t.csv" | grep -q ',collision:west,b43972def416b019,builtin,builtin$' ||
    { echo "last event: $(tail -1 "$tmp/t.csv" | cut -d, -f42-)"; exit 1; }
  grep -q ',eat:west:[0-9]*,' "$tmp/t.csv" || { echo "no eat event"; exit 1; }
  ;;
compare)
  out=$("$duel" play builtin:forager-hunter builtin:spinner --games 288)
  echo "$out" | grep -q "wins 288, B builtin:spinner wins 0" || { echo "$out"; exit 1; }
  echo "$out" | grep -q "^A is superior" || { echo "$out"; exit 1; }
  ;;
*)
  echo "unknown check $what"; exit 2 ;;
esac
echo "ok: $what"
