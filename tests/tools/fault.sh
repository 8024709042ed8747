#!/usr/bin/env bash
# fault.sh DUEL_EVOLVE FAULT_SHIM CONFIG [STRIDE] - every write, fsync and rename of a short run and of its resume made to
# fail in turn (tests/tools/fault_shim.c under LD_PRELOAD): each time the command exits non-zero with one line on stderr,
# and a resume without the fault then gives the run directory of an uninterrupted run, byte for byte (timings and
# log.txt aside). STRIDE k > 1 tries every k-th call only (the sanitizer build, where each run is slow).
set -euo pipefail
duel=$1 shim=$2 cfg=$3 stride=${4:-1}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
gens=3
# under the sanitizer build the shim comes before libasan: tell ASan that is fine
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"

# a run directory's content without timings (generations.csv's last column) and the log
digest() {
  local d=$1
  [ -f "$d/checkpoint.bin" ] || { echo "no checkpoint"; return; }
  (cd "$d" && cut -d, -f1-12 generations.csv && cat config.ini dominance.csv && md5sum checkpoint.bin champions/*)
}

"$duel" run --config "$cfg" --out "$tmp/ref" --generations $gens --quiet
digest "$tmp/ref" > "$tmp/ref.txt"

# the calls of each kind a run makes, then a resume of 2 more generations
count() { # count OP: sets run_calls and resume_calls
  NEAT_FAULT_OPS=$1 NEAT_FAULT_COUNT="$tmp/count" LD_PRELOAD="$shim" "$duel" run --config "$cfg" --out "$tmp/c-$1" \
    --generations 1 --quiet
  run_calls=$(cat "$tmp/count")
  NEAT_FAULT_OPS=$1 NEAT_FAULT_COUNT="$tmp/count" LD_PRELOAD="$shim" "$duel" resume "$tmp/c-$1" --generations $gens --quiet
  resume_calls=$(cat "$tmp/count")
  [ "$run_calls" -gt 0 ] && [ "$resume_calls" -gt 0 ] || fail "the shim counted $run_calls and $resume_calls calls of $1"
}

check_failed() { # check_failed WHAT RC ERRFILE
  [ "$2" -ne 0 ] || fail "$1: exit 0 with a failing disk"
  [ "$(wc -l < "$3")" -eq 1 ] || fail "$1: not one line on stderr: $(cat "$3")"
  grep -q "^duel_evolve: .*\(cannot\|failed\)" "$3" || fail "$1: $(cat "$3")"
}

finish() { # finish DIR: resume without the fault (or run again when the failure came before config.ini existed)
  if [ -f "$1/config.ini" ]; then
    "$duel" resume "$1" --generations $gens --quiet 2> "$tmp/resume.err" || fail "resume after the fault: $(cat "$tmp/resume.err")"
  else
    "$duel" run --config "$cfg" --out "$1" --generations $gens --quiet || fail "run after the fault"
  fi
  digest "$1" > "$tmp/got.txt"
  cmp -s "$tmp/ref.txt" "$tmp/got.txt" || { diff "$tmp/ref.txt" "$tmp/got.txt" | head || true; fail "$2: differs from the uninterrupted run"; }
}

# durability: every rename (checkpoint, config, blobs, rewritten CSVs) is followed by a sync of its directory,
# and every file is synced before it is renamed
NEAT_FAULT_TRACE="$tmp/trace" LD_PRELOAD="$shim" "$duel" run --config "$cfg" --out "$tmp/t" --generations 2 --quiet
awk '$1 == "rename" { r++; want = 1; next } want && !($1 == "fsync" && $2 == "dir") { print "after rename: " $0; bad = 1 }
     { want = 0 } END { exit bad || r < 4 }' "$tmp/trace" || fail "a rename without a directory sync after it"
awk 'prev != "" && $1 == "rename" && prev != "fsync file" { print; bad = 1 } { prev = $1 " " $2 } END { exit bad }' \
  "$tmp/trace" || fail "a file renamed without an fsync before it"
grep -q "rename .*/checkpoint.bin" "$tmp/trace" || fail "no checkpoint rename traced"

n=0
summary=""
for op in write fsync rename; do
  count $op
  summary="$summary, $op $run_calls + $resume_calls"
  for at in $(seq 1 "$stride" "$run_calls"); do
    d=$tmp/r-$op-$at
    rc=0
    NEAT_FAULT_OPS=$op NEAT_FAULT_AT=$at LD_PRELOAD="$shim" "$duel" run --config "$cfg" --out "$d" --generations 1 \
      --quiet 2> "$tmp/err" || rc=$?
    check_failed "run, $op $at" "$rc" "$tmp/err"
    finish "$d" "run, $op $at"
    n=$((n + 1))
    rm -rf "$d"
  done
  for at in $(seq 1 "$stride" "$resume_calls"); do
    d=$tmp/s-$op-$at
    "$duel" run --config "$cfg" --out "$d" --generations 1 --quiet
    rc=0
    NEAT_FAULT_OPS=$op NEAT_FAULT_AT=$at LD_PRELOAD="$shim" "$duel" resume "$d" --generations $gens --quiet \
      2> "$tmp/err" || rc=$?
    check_failed "resume, $op $at" "$rc" "$tmp/err"
    finish "$d" "resume, $op $at"
    n=$((n + 1))
    rm -rf "$d"
  done
done
[ "$n" -gt $((20 / stride)) ] || fail "only $n faults injected"
echo "ok: $n faults injected (calls of a run + its resume:${summary#,}); each failed with one line, and a resume then gave the uninterrupted run"
