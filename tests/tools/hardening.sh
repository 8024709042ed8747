#!/usr/bin/env bash
# hardening.sh DUEL_EVOLVE NEAT_BENCH CONFIG CHECK - input and output that once lost data or passed silently: INI files
# (directories, long lines, duplicate keys, number syntax), a run directory whose checkpoint is gone, traces through
# a temporary file, failing standard output, stale temporary files.
set -euo pipefail
duel=$1 bench=$2 cfg=$3 what=$4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=/dev/null
. "$(dirname "$0")/cli_lib.sh"
snapshot() { (cd "$1" && find . -type f ! -name .lock -print0 | sort -z | xargs -0 md5sum); }

case "$what" in
ini)
  # a directory is not a configuration (it used to read as an empty file and start the 500-generation defaults)
  mkdir "$tmp/dir.ini"
  expect_bad "dir.ini: not a regular file" run --config "$tmp/dir.ini" --out "$tmp/never"
  expect_bad "dir.ini: not a regular file" config --dump --config "$tmp/dir.ini"
  # a long comment whose tail reads like a key (inih cut lines at 199 characters and read the tail as a line)
  printf '[neat]\n; %s pop_size = 3\n' "$(printf 'x%.0s' $(seq 230))" > "$tmp/long.ini"
  "$duel" config --dump --config "$tmp/long.ini" | grep -qx "pop_size = 256" || fail "a comment set pop_size"
  printf '[neat]\n; %s\n' "$(printf 'x%.0s' $(seq 1000))" > "$tmp/toolong.ini"
  expect_bad "toolong.ini:2: a line of 1002 characters (at most 1000)" config --dump --config "$tmp/toolong.ini"
  printf '[neat]\npop_size = 32\nc1 = 1\npop_size = 64\n' > "$tmp/dup.ini"
  expect_bad "dup.ini:4: 'pop_size' given a second time in \[neat\] (first on line 2)" run --config "$tmp/dup.ini" --out "$tmp/never"
  # number syntax: integers are decimal digits; reals may have an exponent
  for v in 0x10 1e2 32.0 +32 " 3 2" "32 ; comment" -1 inf; do
    printf '[neat]\npop_size = %s\n' "$v" > "$tmp/num.ini"
    expect_bad "num.ini:2: bad value '.*' for pop_size: expected an integer" config --dump --config "$tmp/num.ini"
  done
  for v in 0x1p1 inf nan 1e999 1e "" .; do
    printf '[neat]\nc1 = %s\n' "$v" > "$tmp/real.ini"
    expect_bad "real.ini:2: bad value '.*' for c1: expected a number" config --dump --config "$tmp/real.ini"
  done
  printf '[neat]\nc1 = 25e-1\nc2 = -0\nc3 = .5\n' > "$tmp/ok.ini"
  "$duel" config --dump --config "$tmp/ok.ini" > "$tmp/ok.txt"
  grep -qx "c1 = 2.5" "$tmp/ok.txt" && grep -qx "c3 = 0.5" "$tmp/ok.txt" || fail "reals: $(grep '^c[123] ' "$tmp/ok.txt")"
  expect_bad "bad value '0x20' for pop_size" config --dump --set pop_size=0x20
  expect_bad "an override of 1010 characters (at most 1000)" config --dump --set "c1=$(printf '1%.0s' $(seq 1007))"
  # the rest of the syntax
  printf 'pop_size = 3\n' > "$tmp/nosec.ini"
  expect_bad "nosec.ini:1: key 'pop_size' before any \[section\]" config --dump --config "$tmp/nosec.ini"
  printf '[neat\n' > "$tmp/hdr.ini"
  expect_bad "hdr.ini:1: a section header is \[name\] alone on its line" config --dump --config "$tmp/hdr.ini"
  printf '[neat]\npop_size\n' > "$tmp/noeq.ini"
  expect_bad "noeq.ini:2: expected key = value" config --dump --config "$tmp/noeq.ini"
  printf '[neat]\n= 3\n' > "$tmp/nokey.ini"
  expect_bad "nokey.ini:2: a value without a key" config --dump --config "$tmp/nokey.ini"
  printf '[neat]\npop_size = 3\0\n' > "$tmp/nul.ini"
  expect_bad "nul.ini:2: a NUL byte" config --dump --config "$tmp/nul.ini"
  mkfifo "$tmp/fifo.ini"
  expect_bad "fifo.ini: not a regular file" config --dump --config "$tmp/fifo.ini" # not waiting for a writer
  printf '\357\273\277[neat]\npop_size = 40\n' > "$tmp/bom.ini"
  "$duel" config --dump --config "$tmp/bom.ini" | grep -qx "pop_size = 40" || fail "a UTF-8 byte order mark"
  printf '[neat]\r\npop_size = 40\r\n' > "$tmp/crlf.ini"
  "$duel" config --dump --config "$tmp/crlf.ini" | grep -qx "pop_size = 40" || fail "CRLF lines"
  [ ! -e "$tmp/never" ] || fail "a bad configuration created the run directory"
  ;;
bench-ini)
  mkdir "$tmp/dir.ini"
  rc=0; msg=$("$bench" xor --config "$tmp/dir.ini" 2>&1 >/dev/null) || rc=$?
  [ "$rc" -eq 2 ] && echo "$msg" | grep -q "dir.ini: not a regular file" || fail "neat_bench --config DIR: $rc $msg"
  printf '[neat]\npop_size = 150\npop_size = 150\n' > "$tmp/dup.ini"
  rc=0; msg=$("$bench" xor --config "$tmp/dup.ini" 2>&1 >/dev/null) || rc=$?
  [ "$rc" -eq 2 ] && echo "$msg" | grep -q "dup.ini:3: 'pop_size' given a second time" || fail "neat_bench duplicate: $rc $msg"
  ;;
lost-checkpoint)
  # a run whose checkpoint is gone is refused, not restarted over its recorded generations
  "$duel" run --config "$cfg" --out "$tmp/r" --generations 3 --quiet
  rm "$tmp/r/checkpoint.bin"
  snapshot "$tmp/r" > "$tmp/before"
  expect_bad "checkpoint.bin: missing, but the run directory holds 4 rows of generations.csv and 2 champion blobs" resume "$tmp/r"
  expect_bad "has no checkpoint.bin but holds 4 rows of generations.csv and 2 champion blobs" \
    run --config "$cfg" --out "$tmp/r"
  snapshot "$tmp/r" > "$tmp/after"
  cmp -s "$tmp/before" "$tmp/after" || fail "a refused resume changed the directory"
  # a run that died during generation 0 (its rows written, no checkpoint yet) still starts over
  "$duel" run --config "$cfg" --out "$tmp/z" --generations 1 --quiet
  rm "$tmp/z/checkpoint.bin"
  "$duel" resume "$tmp/z" --generations 2 --quiet
  [ "$(tail -n +2 "$tmp/z/generations.csv" | cut -d, -f1 | paste -sd' ')" = "0 0 1 1" ] || fail "generation 0 redone: $(cat "$tmp/z/generations.csv")"
  ;;
trace)
  # --trace goes through TRACE.tmp: a failing --lcm-log leaves an existing trace as it was
  "$duel" play builtin:idle builtin:spinner --trace "$tmp/t.csv" > /dev/null
  cp "$tmp/t.csv" "$tmp/keep.csv"
  expect_bad "nodir/x.lcm: cannot write" play builtin:idle builtin:forager --trace "$tmp/t.csv" --lcm-log "$tmp/nodir/x.lcm"
  cmp -s "$tmp/keep.csv" "$tmp/t.csv" || fail "the trace was overwritten by a failed play"
  [ ! -e "$tmp/t.csv.tmp" ] || fail "t.csv.tmp left behind"
  # a stale TRACE.tmp of a killed play is taken over
  printf 'stale' > "$tmp/t.csv.tmp"
  "$duel" play builtin:idle builtin:forager --trace "$tmp/t.csv" > /dev/null
  head -1 "$tmp/t.csv" | grep -q "^t," || fail "no trace written"
  [ ! -e "$tmp/t.csv.tmp" ] || fail "t.csv.tmp left behind"
  # the same for LCM logs (a killed world node leaves FILE.lcm.tmp)
  printf 'stale' > "$tmp/g.lcm.tmp"
  "$duel" play builtin:idle builtin:forager --lcm-log "$tmp/g.lcm" > /dev/null
  [ ! -e "$tmp/g.lcm.tmp" ] && "$duel" log info "$tmp/g.lcm" > /dev/null || fail "g.lcm.tmp left, or a bad log"
  ;;
links)
  # an output named by a symbolic link replaces the file it points to and keeps the link; one that is no
  # regular file (a pipe, a device) is written in place, never renamed over (as root, /dev/stdout once was)
  : > "$tmp/real.csv" # empty: nothing to lose
  ln -s real.csv "$tmp/link.csv"
  "$duel" play builtin:idle builtin:forager --trace "$tmp/link.csv" > /dev/null
  [ -L "$tmp/link.csv" ] || fail "the link was replaced by a file"
  head -1 "$tmp/real.csv" | grep -q "^t," || fail "the link's target was not written"
  ln -s /dev/null "$tmp/null"
  "$duel" play builtin:idle builtin:forager --trace "$tmp/null" --lcm-log "$tmp/null" > /dev/null
  [ -L "$tmp/null" ] && [ -c /dev/null ] || fail "a link to /dev/null was replaced"
  mkfifo "$tmp/fifo"
  cat "$tmp/fifo" > "$tmp/from-fifo.csv" &
  reader=$!
  "$duel" play builtin:idle builtin:forager --trace "$tmp/fifo" > /dev/null
  wait "$reader"
  [ -p "$tmp/fifo" ] || fail "the FIFO was replaced by a file"
  cmp -s "$tmp/from-fifo.csv" "$tmp/real.csv" || fail "the trace through the FIFO differs"
  : > "$tmp/real2.c"
  ln -s "$tmp/real2.c" "$tmp/link2.c"
  "$duel" run --config "$cfg" --out "$tmp/r" --generations 1 --quiet
  "$duel" export "$tmp/r/champions/gen-00000.blob" --c-array x -o "$tmp/link2.c"
  [ -L "$tmp/link2.c" ] && grep -q "x\[" "$tmp/real2.c" || fail "export -o through a link"
  # a symbolic link planted where a temporary goes is removed, not followed
  printf 'keep\n' > "$tmp/victim"
  ln -s "$tmp/victim" "$tmp/t.csv.tmp"
  "$duel" play builtin:idle builtin:forager --trace "$tmp/t.csv" > /dev/null
  [ "$(cat "$tmp/victim")" = keep ] || fail "a planted link was followed"
  ;;
stdout)
  # a command whose output cannot be written fails, with one line
  "$duel" run --config "$cfg" --out "$tmp/r" --generations 2 --quiet
  "$duel" play builtin:idle builtin:forager --lcm-log "$tmp/g.lcm" > /dev/null
  for cmd in "config --dump" "play builtin:idle builtin:forager" "play builtin:idle builtin:forager --games 288" \
             "ladder $tmp/r" "log info $tmp/g.lcm" "log dump $tmp/g.lcm" "inspect $tmp/r/champions/gen-00001.blob" \
             "dot $tmp/r/champions/gen-00001.blob" "run --config $cfg --out $tmp/j --generations 1 --quiet --json" \
             "export $tmp/r/champions/gen-00001.blob --c-array x" "--help"; do
    rc=0
    # shellcheck disable=SC2086
    "$duel" $cmd > /dev/full 2> "$tmp/err" || rc=$?
    [ "$rc" -ne 0 ] || fail "$cmd > /dev/full: exit 0"
    [ "$(wc -l < "$tmp/err")" -eq 1 ] && grep -q "cannot write standard output: No space left on device" "$tmp/err" ||
      fail "$cmd > /dev/full: $(cat "$tmp/err")"
  done
  rc=0; "$bench" xor --runs 2 --quiet > /dev/full 2> "$tmp/err" || rc=$?
  [ "$rc" -ne 0 ] && grep -q "cannot write standard output" "$tmp/err" || fail "neat_bench > /dev/full: $rc $(cat "$tmp/err")"
  ;;
*)
  echo "unknown check $what"; exit 2 ;;
esac
echo "ok: $what"
