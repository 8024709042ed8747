#!/usr/bin/env bash
# safety.sh DUEL_EVOLVE CONFIG PLAN CHECK - no command destroys a file it does not own, every record is rebuilt or
# refused with advice that works, every read is bounded (issue 40; docs/hardening.md, "Files that are not ours").
# CONFIG is a small run (tests/tools/coev-small.ini), PLAN a small experiment (tests/tools/tiny-plan.ini).
set -euo pipefail
duel=$1 cfg=$2 plan=$3 what=$4
tmp=$(mktemp -d)
pids=()
trap 'for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null || true; done; rm -rf "$tmp"' EXIT
# shellcheck source=/dev/null
. "$(dirname "$0")/cli_lib.sh"
snapshot() { (cd "$1" && find . -type f ! -name .lock -print0 | sort -z | xargs -0 md5sum); }

case "$what" in
rundir)
  # class 2: run --out an existing directory that is not a run touches nothing there
  mkdir "$tmp/mine"
  printf 'my notes\n' > "$tmp/mine/notes.txt"
  printf 'keep me\n' > "$tmp/mine/generations.csv"
  printf 'keep me too\n' > "$tmp/mine/dominance.csv"
  before=$(snapshot "$tmp/mine"; ls -A "$tmp/mine")
  expect_bad "mine is not empty and not a run directory (it holds 'notes.txt', which is not a run's): choose another --out" \
    run --config "$cfg" --out "$tmp/mine" --generations 1
  [ "$(snapshot "$tmp/mine"; ls -A "$tmp/mine")" = "$before" ] || fail "run --out touched a directory that is not a run"
  # an experiment directory is not a run
  "$duel" experiment "$plan" --out "$tmp/exp" --set generations=1 --quiet > /dev/null
  before=$(snapshot "$tmp/exp")
  expect_bad "exp is not empty and not a run directory (it holds '.*', which is not a run's)" \
    run --config "$cfg" --out "$tmp/exp" --generations 1
  [ "$(snapshot "$tmp/exp")" = "$before" ] || fail "run --out changed an experiment directory"
  # a config.ini that no run wrote
  mkdir "$tmp/cfg"
  printf '[neat]\npop_size = 8\n' > "$tmp/cfg/config.ini"
  expect_bad "cfg is not empty and not a run directory (it holds a config.ini that a run did not write)" \
    run --config "$cfg" --out "$tmp/cfg" --generations 1
  grep -q "pop_size = 8" "$tmp/cfg/config.ini" || fail "config.ini replaced"
  # what still works: an empty directory, and the remains of a run that died before its first checkpoint
  mkdir "$tmp/empty"
  "$duel" run --config "$cfg" --out "$tmp/empty" --generations 1 --quiet
  "$duel" run --config "$cfg" --out "$tmp/died" --generations 1 --quiet
  rm "$tmp/died/checkpoint.bin" "$tmp/died/champions/"*
  "$duel" run --config "$cfg" --out "$tmp/died" --generations 1 --quiet || fail "a run that died before its checkpoint"
  ;;
lock)
  # class 7: deleting .lock while a run works does not let a second writer in; a .lock that is a link is not followed
  "$duel" run --config "$cfg" --out "$tmp/r" --generations 1 --quiet
  "$duel" resume "$tmp/r" --generations 100000 --quiet > /dev/null 2>&1 &
  pids+=($!)
  for _ in $(seq 100); do grep -q "resume at" "$tmp/r/log.txt" 2>/dev/null && break; sleep 0.1; done
  rm "$tmp/r/.lock"
  expect_bad "r is in use by another duel_evolve run or resume" resume "$tmp/r" --generations 100000
  kill -9 "${pids[0]}"
  wait "${pids[0]}" 2>/dev/null || true
  rm -f "$tmp/r/.lock"
  ln -s "$tmp/planted" "$tmp/r/.lock"
  expect_bad "r/.lock is a symbolic link: refusing to follow it (remove it)" resume "$tmp/r" --generations 3
  [ ! -e "$tmp/planted" ] || fail "the .lock link's target was created"
  mkdir "$tmp/e"
  ln -s "$tmp/planted" "$tmp/e/.lock"
  expect_bad "experiment: .*e: .lock is a symbolic link" experiment "$plan" --out "$tmp/e"
  [ ! -e "$tmp/planted" ] || fail "the experiment's .lock link's target was created"
  ;;
bounds)
  # class 4: every reader of a run directory has a cap and reads regular files only (no FIFO wait, no endless file)
  "$duel" run --config "$cfg" --out "$tmp/r" --generations 2 --quiet
  cp -r "$tmp/r" "$tmp/keep"
  for f in generations.csv dominance.csv; do
    rm "$tmp/r/$f"
    mkfifo "$tmp/r/$f"
    timeout 20 "$duel" resume "$tmp/r" --generations 3 --quiet 2> "$tmp/err" && fail "resume read a FIFO $f" || true
    grep -q "$f.*not a regular file" "$tmp/err" || fail "FIFO $f: $(cat "$tmp/err")"
    rm "$tmp/r/$f"
    ln -s /dev/zero "$tmp/r/$f"
    timeout 20 "$duel" resume "$tmp/r" --generations 3 --quiet 2> "$tmp/err" && fail "resume read /dev/zero as $f" || true
    grep -q "$f.*not a regular file" "$tmp/err" || fail "/dev/zero as $f: $(cat "$tmp/err")"
    rm "$tmp/r/$f"
    cp "$tmp/keep/$f" "$tmp/r/$f"
  done
  truncate -s 300M "$tmp/r/generations.csv" # sparse: costs no disk
  timeout 20 "$duel" resume "$tmp/r" --generations 3 --quiet 2> "$tmp/err" && fail "resume read a 300 MB file" || true
  grep -q "generations.csv.*too large" "$tmp/err" || fail "300 MB generations.csv: $(cat "$tmp/err")"
  cp "$tmp/keep/generations.csv" "$tmp/r/generations.csv"
  truncate -s 300M "$tmp/r/dominance.csv" # the run's own record, damaged: rebuilt from the checkpoint
  timeout 20 "$duel" resume "$tmp/r" --quiet || fail "resume did not rebuild a 300 MB dominance.csv"
  cmp "$tmp/keep/dominance.csv" "$tmp/r/dominance.csv" || fail "a 300 MB dominance.csv not rebuilt"
  rm "$tmp/r/dominance.csv"
  mkfifo "$tmp/r/dominance.csv"
  timeout 20 "$duel" ladder "$tmp/r" --top 2> "$tmp/err" && fail "ladder read a FIFO" || true
  grep -q "dominance.csv.*not a regular file" "$tmp/err" || fail "ladder FIFO: $(cat "$tmp/err")"
  mkfifo "$tmp/fifo"
  timeout 20 "$duel" inspect "$tmp/fifo" 2> "$tmp/err" && fail "inspect read a FIFO" || true
  [ -s "$tmp/err" ] || fail "inspect of a FIFO said nothing"
  expect_bad "fifo: cannot open: not a regular file" log info "$tmp/fifo"
  ;;
records)
  # class 3: what the checkpoint holds is rebuilt by resume, byte for byte; what it does not is refused with advice
  # that works; no reader drops a cut last row silently
  "$duel" run --config "$cfg" --out "$tmp/ref" --generations 4 --quiet
  [ "$(wc -l < "$tmp/ref/dominance.csv")" -ge 3 ] || fail "too few levels to test: $(cat "$tmp/ref/dominance.csv")"
  cp -r "$tmp/ref" "$tmp/r"
  head -c -1 "$tmp/ref/dominance.csv" > "$tmp/r/dominance.csv" # the last row lost its newline
  expect_bad "dominance.csv:[0-9]*: the last row is cut short (no newline): resuming the run rebuilds the file" \
    ladder "$tmp/r" --top
  expect_bad "dominance.csv:[0-9]*: the last row is cut short" compare "$tmp/r" --against "$tmp/ref"
  "$duel" resume "$tmp/r" --quiet # a finished run: resume only repairs
  cmp "$tmp/ref/dominance.csv" "$tmp/r/dominance.csv" || fail "a cut dominance.csv not rebuilt"
  grep -q "resume: dominance.csv rebuilt from the checkpoint" "$tmp/r/log.txt" || fail "the rebuild not logged"
  rm "$tmp/r/dominance.csv"
  "$duel" resume "$tmp/r" --quiet
  cmp "$tmp/ref/dominance.csv" "$tmp/r/dominance.csv" || fail "a deleted dominance.csv not rebuilt"
  sed -i 2d "$tmp/r/dominance.csv"
  "$duel" ladder "$tmp/r" --top > /dev/null 2>&1 && fail "ladder took a dominance.csv without level 1" || true
  "$duel" resume "$tmp/r" --generations 5 --quiet
  "$duel" resume "$tmp/ref" --generations 5 --quiet
  cmp "$tmp/ref/dominance.csv" "$tmp/r/dominance.csv" || fail "a row dropped from dominance.csv not rebuilt"
  cmp "$tmp/ref/checkpoint.bin" "$tmp/r/checkpoint.bin" || fail "the repaired run went on differently"
  # generations.csv rows are measured as they happen: lost ones are refused, with advice that works
  cp -r "$tmp/ref" "$tmp/g"
  sed -i 4d "$tmp/g/generations.csv"
  expect_bad "generations.csv:4: generation 1 B follows generation 0 B: rows are missing: rows lost cannot be rebuilt" \
    resume "$tmp/g" --generations 6
  head -3 "$tmp/ref/generations.csv" > "$tmp/g/generations.csv"
  expect_bad "g/generations.csv holds 1 generation but the checkpoint 5: rows lost cannot be rebuilt" \
    resume "$tmp/g" --generations 6
  head -c -1 "$tmp/ref/generations.csv" > "$tmp/g/generations.csv" # generation 4's B row torn: lost
  cp "$tmp/g/generations.csv" "$tmp/cut.csv"
  expect_bad "g/generations.csv holds 4 generations but the checkpoint 5: rows lost cannot be rebuilt" \
    resume "$tmp/g" --generations 6
  cmp "$tmp/cut.csv" "$tmp/g/generations.csv" || fail "a refused resume changed generations.csv"
  # the advice works: the run played again from its config.ini gives the same rows and the same checkpoint
  "$duel" run --config "$tmp/ref/config.ini" --out "$tmp/again" --quiet
  diff <(cut -d, -f1-16 "$tmp/ref/generations.csv") <(cut -d, -f1-16 "$tmp/again/generations.csv") ||
    fail "the run played again differs"
  cmp "$tmp/ref/checkpoint.bin" "$tmp/again/checkpoint.bin" || fail "the run played again has another checkpoint"
  # in an experiment: the report refuses, and deleting the run's directory then experiment resume repairs it
  "$duel" experiment "$plan" --out "$tmp/x" --set generations=2 --quiet > /dev/null
  cp "$tmp/x/report/table1.csv" "$tmp/table1.csv"
  cp -r "$tmp/x/runs/complexify-2" "$tmp/c2"
  sed -i 3d "$tmp/x/runs/complexify-2/generations.csv"
  expect_bad "complexify-2/generations.csv:3: .*rows are missing: .*delete the run's directory and duel_evolve experiment resume plays it again" \
    experiment report "$tmp/x"
  head -c -1 "$tmp/c2/generations.csv" > "$tmp/x/runs/complexify-2/generations.csv"
  expect_bad "generations.csv:[0-9]*: the last row is cut short (no newline): resuming the run cuts it" \
    experiment report "$tmp/x"
  rm -r "$tmp/x/runs/complexify-2"
  "$duel" experiment resume "$tmp/x" --quiet > /dev/null
  cmp "$tmp/c2/checkpoint.bin" "$tmp/x/runs/complexify-2/checkpoint.bin" || fail "the run played again differs"
  diff <(cut -d, -f1-4 "$tmp/table1.csv") <(cut -d, -f1-4 "$tmp/x/report/table1.csv") || fail "another table"
  # a cut dominance.csv in a finished experiment run: resume the run, as the message says
  head -c -1 "$tmp/c2/dominance.csv" > "$tmp/x/runs/complexify-2/dominance.csv"
  expect_bad "the last row is cut short (no newline): resuming the run rebuilds" experiment report "$tmp/x"
  "$duel" resume "$tmp/x/runs/complexify-2" --quiet
  "$duel" experiment report "$tmp/x" > /dev/null
  ;;
*)
  fail "unknown check $what"
  ;;
esac
echo "safety $what: ok"
