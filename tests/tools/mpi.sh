#!/usr/bin/env bash
# mpi.sh - duel_evolve under mpirun on this machine (shared memory and loopback only): runs and experiments with
# 1, 2, 3 and 5 ranks byte for byte those of one process; a rank killed, then resumed with another N; bad launches.
set -euo pipefail
duel=$1
what=$2
cfg=$3
plan=$4
skew=${5:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
# shellcheck source=/dev/null
. "$(dirname "$0")/cli_lib.sh"
# as root (CI), and on no network but this machine's
mpi=(mpirun --allow-run-as-root --oversubscribe --mca pml ob1 --mca btl self,vader,tcp --mca btl_tcp_if_include lo
     --mca oob_tcp_if_include lo)

# Everything of a run directory but timings and the log (as tests/tools/duel_run.sh)
same_run() {
  diff -r "$1/champions" "$2/champions" || fail "champions differ"
  cmp "$1/dominance.csv" "$2/dominance.csv" || fail "dominance.csv differs"
  cmp "$1/checkpoint.bin" "$2/checkpoint.bin" || fail "checkpoint differs"
  diff <(cut -d, -f1-16 "$1/generations.csv") <(cut -d, -f1-16 "$2/generations.csv") || fail "generations.csv differs"
}
# Every file of an experiment but timings and logs (as tests/tools/experiment.sh)
snapshot() {
  (cd "$1" && find . -type f ! -name '.lock' ! -name 'log.txt' ! -name 'timing.csv' ! -name 'generations.csv' \
    -print0 | sort -z | xargs -0 sha256sum
   for g in runs/*/generations.csv; do [ -f "$g" ] && echo "$g $(cut -d, -f1-16 "$g" | sha256sum)"; done) || true
}
# The pid of rank R of a job whose command line contains PATTERN, once it is there
rank_pid() {
  local r=$1 pattern=$2 p i
  for i in $(seq 100); do
    for p in $(pgrep -f -- "$pattern" || true); do
      if tr '\0' '\n' < "/proc/$p/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$r"; then echo "$p"; return; fi
    done
    sleep 0.1
  done
  fail "no rank $r of '$pattern'"
}
# until generations.csv of DIR has N generations (or the job PID ends)
wait_gens() {
  while kill -0 "$2" 2>/dev/null && [ "$(cut -d, -f1 "$1/generations.csv" 2>/dev/null | sort -u | grep -c '^[0-9]')" -lt "$3" ]
  do sleep 0.05; done
}
# freeze NAME RANK DIR PATTERN ARGS...: duel_evolve ARGS on 3 ranks with a 2 s deadline base; once DIR has 3
# generations, rank RANK stopped (SIGSTOP): the job must end within 60 s, not 0, with a line on NAME.err matching
# PATTERN
freeze() {
  local name=$1 rank=$2 dir=$3 pattern=$4 job frozen start rc=0
  shift 4
  "${mpi[@]}" -np 3 -x DUEL_MPI_WAIT=2 "$duel" "$@" 2> "$name.err" & job=$!
  wait_gens "$dir" $job 3
  frozen=$(rank_pid "$rank" "$*")
  kill -STOP "$frozen"
  start=$SECONDS
  wait $job || rc=$?
  kill -9 "$frozen" 2>/dev/null || true
  [ "$rc" -ne 0 ] || fail "$name: the job went on without the frozen rank $rank"
  [ $((SECONDS - start)) -lt 60 ] || fail "$name: the job took $((SECONDS - start)) s to end"
  grep -q "$pattern" "$name.err" || fail "$name: no line names the frozen rank $rank: $(cat "$name.err")"
}
# a tiny experiment: 2 methods, 3 runs; and one of 1 method, 2 runs (fewer runs than ranks: groups)
cp -r "$(dirname "$plan")/../../configs" presets
cat > plan.ini <<PLAN
[experiment]
presets = $tmp/presets
reference = complexify
seed = 3
[all runs]
generations = 5
pop_size = 16
compare_configs = 12
[method complexify]
preset = paper
runs = 2
[method fixed-5]
preset = fixed-5
runs = 1
PLAN
sed '/^\[method fixed-5\]/,$d' plan.ini > plan-one.ini

case "$what" in
run)
  "$duel" run --config "$cfg" --out ref --quiet --generations 6
  for nt in 1-1 1-2 2-2 3-1; do
    "${mpi[@]}" -np "${nt%-*}" "$duel" run --config "$cfg" --out "n$nt" --threads "${nt#*-}" --quiet --generations 6
    same_run ref "n$nt"
  done
  grep -q "mpi: 3 ranks, 1 thread on rank 0" n3-1/log.txt || fail "log.txt: $(grep mpi n3-1/log.txt)"
  grep -q "mpi: 3 MPI ranks; games sent in [0-9]* messages of [0-9]* bytes" n3-1/log.txt ||
    fail "no message count in log.txt"
  # a resume spreads too, and stopping in the middle changes nothing
  "${mpi[@]}" -np 2 "$duel" run --config "$cfg" --out part --generations 3 --quiet
  "${mpi[@]}" -np 3 "$duel" resume part --generations 6 --quiet
  same_run ref part
  # a run in a world of its own, with the propagate step: the rules and the mode reach every rank
  printf '[world]\nfood_range = 300\nwall_range = 90\n[neat]\nnet_step = propagate\n' > world.ini
  cat "$cfg" world.ini > wcfg.ini
  "$duel" run --config wcfg.ini --out wref --quiet --generations 4
  "${mpi[@]}" -np 3 "$duel" run --config wcfg.ini --out wn3 --threads 1 --quiet --generations 4
  same_run wref wn3
  # a run against fixed opponents (builtins and a blob) spreads its games too
  printf '[opponents]\nplay = builtin:forager-hunter, %s, builtin:forager\ngames = comparison:2\n' \
    "$tmp/ref/champions/gen-00003.blob" > opp.ini
  cat "$cfg" world.ini opp.ini > fcfg.ini
  "$duel" run --config fcfg.ini --out fref --quiet --generations 5 --set strength_every=2
  "${mpi[@]}" -np 3 "$duel" run --config fcfg.ini --out fn3 --threads 1 --quiet --generations 5 --set strength_every=2
  cmp fref/checkpoint.bin fn3/checkpoint.bin || fail "fixed: checkpoint differs"
  cmp fref/strength.csv fn3/strength.csv || fail "fixed: strength.csv differs"
  diff -r fref/champions fn3/champions || fail "fixed: champions differ"
  grep -q "mpi: 3 MPI ranks; games sent in [1-9][0-9]* messages" fn3/log.txt || fail "fixed: no games went to the ranks"
  echo "run: ok"
  ;;
experiment)
  "$duel" experiment plan.ini --out E1 --quiet
  "$duel" experiment plan-one.ini --out O1 --quiet
  for n in 2 3; do
    "${mpi[@]}" -np $n "$duel" experiment plan.ini --out "E$n" --quiet
    diff <(snapshot E1) <(snapshot "E$n") > snap.diff || fail "-np $n: other files: $(head -5 snap.diff)"
  done
  # 5 ranks for 2 runs: two groups of two ranks, each run's games spread over its group
  "${mpi[@]}" -np 5 "$duel" experiment plan-one.ini --out O5 2> o5.err
  grep -q "5 MPI ranks as 2 slots (2 ranks x 1 threads, 2 ranks x 1 threads)" o5.err || fail "groups: $(head -3 o5.err)"
  grep -q "mpi: 2 ranks" O5/runs/complexify-1/log.txt || fail "the group did not spread the run's games"
  diff <(snapshot O1) <(snapshot O5) > snap.diff || fail "-np 5 (groups): other files: $(head -5 snap.diff)"
  echo "experiment: ok"
  ;;
faults)
  # 40 generations: mpirun takes about a second to pass Ctrl-C on, 14 generations on this machine (below)
  "$duel" run --config "$cfg" --out ref --quiet --generations 40
  # a rank killed in the middle of a run ends the job at once, with mpirun's line naming it
  "${mpi[@]}" -np 3 "$duel" run --config "$cfg" --out K --generations 40 --quiet 2> k.err & job=$!
  wait_gens K $job 4
  kill -9 "$(rank_pid 1 "run --config $cfg --out K")"
  start=$SECONDS rc=0
  wait $job || rc=$?
  [ "$rc" -ne 0 ] || fail "the job went on without rank 1"
  [ $((SECONDS - start)) -lt 30 ] || fail "the job took $((SECONDS - start)) s to end"
  grep -q "rank 1 .*exited on signal 9" k.err || fail "no line names the killed rank: $(cat k.err)"
  # resumed with another number of ranks: the run one process plays
  "${mpi[@]}" -np 2 "$duel" resume K --quiet
  same_run ref K
  # a frozen rank (SIGSTOP) ends the job after its deadline (DUEL_MPI_WAIT s here, 60 s by default, plus 0.25 s
  # a game in flight), with a line naming it; it used to hold the job for ever
  freeze f 1 F "mpi: rank 1 has not answered for [0-9]* s (.* games in flight to it, at most [0-9]* s allowed): it is frozen" \
    run --config "$cfg" --out F --generations 40 --quiet
  "$duel" resume F --quiet
  same_run ref F
  # a frozen rank 0: the others wait for its next chunk with no work in flight; its signs of life stop, and after
  # the deadline's base a waiting rank ends the job with a line naming it
  freeze z 0 Z "mpi: rank 0 (on .*) has given no sign of life for [0-9]* s (at most 2 s allowed) while rank [12] waits for a message from it: it is frozen" \
    run --config "$cfg" --out Z --generations 40 --quiet
  "$duel" resume Z --quiet
  same_run ref Z
  # Ctrl-C to mpirun: rank 0 finishes the generation, saves it and releases the others
  "${mpi[@]}" -np 3 "$duel" run --config "$cfg" --out I --generations 40 2> i.err & job=$!
  wait_gens I $job 2
  kill -INT $job
  wait $job || true
  grep -q "interrupted before generation" I/log.txt || fail "Ctrl-C: no clean stop: $(tail -3 i.err)"
  "$duel" resume I --quiet
  same_run ref I
  # an experiment with a rank killed during its runs, continued with 2 ranks: one process's files
  "$duel" experiment plan-one.ini --out E1 --quiet
  "${mpi[@]}" -np 3 "$duel" experiment plan-one.ini --out EK --quiet 2> ek.err & job=$!
  wait_gens EK/runs/complexify-2 $job 2
  kill -9 "$(rank_pid 1 "experiment plan-one.ini --out EK")"
  wait $job 2>/dev/null && fail "the experiment went on without rank 1"
  sleep 0.3 # rank 0's child (its own slot) dies with it
  "${mpi[@]}" -np 2 "$duel" experiment resume EK --quiet
  diff <(snapshot E1) <(snapshot EK) > snap.diff || fail "continued experiment: other files: $(head -5 snap.diff)"
  # an experiment with a rank frozen while it plays a whole run (no deadline from the run's work): rank 0 watches
  # its signs of life, ends the job after the deadline's base, and the experiment continues to the same files
  freeze ez 1 EZ/runs/complexify-2 "mpi: rank 1 (on .*) has given no sign of life for [0-9]* s (at most 2 s allowed) while rank 0 waits for the task it executes" \
    experiment plan-one.ini --out EZ --quiet
  sleep 0.3 # rank 0's child (its own slot) dies with it
  "${mpi[@]}" -np 2 "$duel" experiment resume EZ --quiet
  diff <(snapshot E1) <(snapshot EZ) > snap.diff || fail "continued experiment (frozen rank): other files: $(head -5 snap.diff)"
  echo "faults: ok"
  ;;
bad)
  # one line from rank 0, exit 2 (mpirun adds its own lines about the exit status: not ours)
  mpi_bad() { # mpi_bad PATTERN NP ARGS...
    local pattern=$1 np=$2 rc=0
    shift 2
    "${mpi[@]}" -np "$np" "$@" > out.txt 2> err.txt || rc=$?
    [ "$rc" -ne 0 ] || fail "$*: exit 0"
    [ "$(grep -c '^duel_evolve' err.txt)" -eq 1 ] || fail "$*: not one line: $(cat err.txt)"
    grep -q -- "$pattern" err.txt || fail "$*: expected '$pattern', got: $(grep '^duel_evolve' err.txt)"
  }
  mpi_bad "runs in one process: under mpirun only run, resume and experiment" 2 "$duel" play builtin:forager builtin:hunter
  mpi_bad "5 MPI ranks for a run of 2 x 2 networks: at most 4 ranks" 5 "$duel" run --config "$cfg" --set pop_size=2 --out P
  [ ! -e P/checkpoint.bin ] || fail "a refused run wrote a checkpoint"
  sed 's/^pop_size = 16/pop_size = 2/' plan-one.ini > plan-small.ini
  mpi_bad "11 MPI ranks make groups of 5 ranks, more than the 2 x 2 networks of a complexify run can use" 11 \
    "$duel" experiment plan-small.ini --out X --quiet
  [ ! -e X/runs/complexify-1/checkpoint.bin ] || fail "a refused experiment played"
  # a rank of another build: refused before anything is played
  rc=0
  "${mpi[@]}" -np 1 "$duel" run --config "$cfg" --out S --quiet : -np 1 "$skew" > out.txt 2> err.txt || rc=$?
  [ "$rc" -ne 0 ] || fail "another build on rank 1: exit 0"
  grep -q "^duel_evolve: mpi: rank 1 (on .*) runs another build of duel_evolve than rank 0" err.txt ||
    fail "another build: $(cat err.txt)"
  [ "$(grep -c '^duel_evolve' err.txt)" -eq 1 ] || fail "another build: not one line: $(cat err.txt)"
  [ ! -e S ] || fail "another build: the run started"
  # and the same build passes the check (the helper without its salt would: here duel_evolve on both ranks)
  "${mpi[@]}" -np 2 "$duel" run --config "$cfg" --out T --generations 2 --quiet
  echo "bad: ok"
  ;;
*) fail "unknown check $what" ;;
esac
