#!/usr/bin/env bash
# experiment.sh DUEL PLAN CHECK MODE [--set k=v ...] - duel_evolve experiment. MODE bad: bad plans, exit 2 and
# one line, nothing created. resume: an uninterrupted experiment against one killed (-9 and SIGINT) at three points
# and continued with other job and thread counts: the same files; its report recomputed by CHECK; bad directories
# (another plan, a changed plan or preset, a stray run) refused with nothing touched. report: the committed fixture
# reported again without playing a game, the same tables; a missing comparison and a failing plot.
set -euo pipefail
duel=$1
plan=$(realpath "$2")
check=$(realpath "$3")
mode=$4
shift 4
scale=("$@") # extra --set options: a smaller experiment under the sanitizers
tmp=$(mktemp -d)
trap 'pkill -9 -P $$ 2>/dev/null || true; rm -rf "$tmp"' EXIT
# shellcheck source=/dev/null
. "$(dirname "$0")/cli_lib.sh"
cd "$tmp"

# every file an experiment leaves, timings aside: NAME SHA256 lines
snapshot() {
  (cd "$1" && find . -type f ! -name '.lock' ! -name 'log.txt' ! -name 'timing.csv' ! -name 'generations.csv' \
    -print0 | sort -z | xargs -0 sha256sum
   # generations.csv without its seconds column
   for g in runs/*/generations.csv; do [ -f "$g" ] && echo "$g $(cut -d, -f1-16 "$g" | sha256sum)"; done) || true
}

wait_for() { # wait_for PID TEST...: until the test holds or the process ends
  local pid=$1
  shift
  while kill -0 "$pid" 2>/dev/null && ! "$@"; do sleep 0.1; done
}

case $mode in
bad)
  mkplan() { # mkplan FILE [sed expressions]: the test plan edited
    local f=$1
    shift
    sed -e "" "$@" "$plan" > "$f"
    sed -i "s|^presets = .*|presets = $(dirname "$plan")/../../configs|" "$f"
  }
  mkplan missing.ini -e 's/^preset = fixed-5/preset = fixed-55/'
  expect_bad "fixed-55.ini" experiment missing.ini --out e
  mkplan opt.ini -e 's/^\[method fixed-5\]/[method fixed-5]\ncolour = red/'
  expect_bad "opt.ini:[0-9]*: unknown key 'colour'" experiment opt.ini --out e
  mkplan sect.ini -e 's/^\[all runs\]/[every run]/'
  expect_bad "sect.ini:[0-9]*: unknown section \[every run\]" experiment sect.ini --out e
  mkplan noruns.ini -e '/^runs = 2/d'
  expect_bad "needs runs = N" experiment noruns.ini --out e
  mkplan oneref.ini -e '0,/^runs = 3/s//runs = 1/'
  expect_bad "needs at least 2 runs" experiment oneref.ini --out e
  mkplan nobest.ini -e '/^start = best/d'
  expect_bad "\[method best\]" experiment nobest.ini --out e
  mkplan twice.ini -e 's/^\[method simplify\]/[method fixed-5]/'
  expect_bad "given a second time in \[method fixed-5\]" experiment twice.ini --out e
  mkplan ok.ini
  expect_bad "generationz" experiment ok.ini --out e --set generationz=3
  sed -i 's/^reference = complexify/reference = nobody/' ok.ini
  expect_bad "reference = nobody names no" experiment ok.ini --out e
  expect_bad "where" experiment ok.ini
  expect_bad "unknown option '--frobnicate'" experiment ok.ini --out e --frobnicate
  expect_bad "no plan.ini" experiment report .
  # a directory path too long for plan.ini to be appended (it used to be cut and another file read)
  expect_bad "path is longer than 4190 bytes" experiment report "$(printf 'd/%.0s' $(seq 2100))"
  mkdir full && touch full/x
  mkplan ok2.ini
  expect_bad "not empty and not an experiment directory" experiment ok2.ini --out full
  [ ! -e e ] || fail "a refused plan created its directory"
  # every plan of configs/plans is valid
  for f in "$(dirname "$plan")"/../../configs/plans/*.ini; do
    out=$("$duel" experiment "$f" --dry-run) || fail "$f: $out"
    grep -q "runs, [0-9]* generations in all" <<< "$out" || fail "$f --dry-run: $out"
  done
  "$duel" experiment "$(dirname "$plan")/../../configs/plans/paper.ini" --dry-run |
    grep -q "^38 runs, 19000 generations in all" || fail "the paper's plan is not 38 runs of 500 generations"
  echo "bad plans: ok"
  ;;

resume)
  cp -r "$(dirname "$plan")/../../configs" presets
  sed "s|^presets = .*|presets = $tmp/presets|" "$plan" > plan.ini
  "$duel" experiment plan.ini --out A --jobs 1 --threads 1 --quiet "${scale[@]}"
  python3 "$check" A
  ls A/report/*.png A/report/*.svg > /dev/null || fail "no figures: $(ls A/report)"
  head -c 8 A/report/fig7-complexity.png | od -An -c | grep -q 'P   N   G' || fail "fig7 is not a PNG"
  grep -q '<svg' A/report/fig11-levels.svg || fail "fig11 is not an SVG"
  grep -q '^| complexify | [0-9]* |' A/report/table1.md || fail "table1.md: $(head -8 A/report/table1.md)"

  # B: killed -9 in the middle of a run, SIGINT when the best-topology runs start, -9 again during the comparisons
  "$duel" experiment plan.ini --out B --jobs 2 --threads 2 --quiet "${scale[@]}" &
  pid=$!
  wait_for $pid test -s B/runs/complexify-2/generations.csv
  kill -9 $pid
  wait $pid 2>/dev/null || true
  sleep 0.3 # the runs die with it (PR_SET_PDEATHSIG)
  "$duel" experiment plan.ini --out B --jobs 3 --threads 1 --quiet "${scale[@]}" &
  pid=$!
  wait_for $pid test -e B/best-topology.blob
  kill -INT $pid
  rc=0
  wait $pid || rc=$?
  [ "$rc" -eq 130 ] || [ "$rc" -eq 0 ] || fail "SIGINT: exit $rc"
  "$duel" experiment resume B --jobs 1 --threads 3 --quiet &
  pid=$!
  wait_for $pid test -e B/runs/fixed-5-1/compare-cache.csv
  kill -9 $pid
  wait $pid 2>/dev/null || true
  sleep 0.3
  "$duel" experiment resume B --quiet
  diff <(snapshot A) <(snapshot B) > snap.diff || fail "an interrupted experiment gives other files: $(head -5 snap.diff)"

  # continuing with the same plan changes nothing; a changed plan is refused and changes nothing
  "$duel" experiment plan.ini --out A --quiet "${scale[@]}"
  diff <(snapshot A) <(snapshot B) > /dev/null || fail "continuing a finished experiment changed it"
  expect_bad "A/plan.ini holds another plan: line" experiment plan.ini --out A --set generations=99
  sed -i 's/^c1 = 1.0/c1 = 1.5/' presets/paper.ini
  expect_bad "A/configs/complexify.ini differs from what the plan's preset gives now" experiment plan.ini --out A \
    "${scale[@]}"
  sed -i 's/^c1 = 1.5/c1 = 1.0/' presets/paper.ini
  # a run of another plan in the right place, and a stray directory
  mkdir -p C/runs
  cp A/plan.ini C/
  cp -r A/configs C/
  cp -r A/runs/complexify-1 C/runs/fixed-5-1
  expect_bad "C/runs/fixed-5-1/config.ini belongs to another plan: line" experiment plan.ini --out C "${scale[@]}"
  rm -rf C/runs/fixed-5-1
  mkdir C/runs/zzz
  expect_bad "C/runs/zzz is no run of this plan" experiment plan.ini --out C "${scale[@]}"
  rm -rf C/runs/zzz
  expect_bad "not a finished run\|checkpoint.bin: missing\|dominance.csv" experiment report C
  diff <(snapshot A) <(snapshot B) > /dev/null || fail "a refused continuation changed A"
  echo "resume: ok"
  ;;

report)
  fixture=$(realpath "${scale[0]}")
  cp -r "$fixture" F
  mkdir want
  mv F/report/* want/
  "$duel" experiment report F 2> report.err || fail "report: $(cat report.err)"
  for f in want/*; do
    cmp "$f" "F/report/$(basename "$f")" || fail "report of the fixture: $(basename "$f") differs"
  done
  ls F/report/*.png F/report/*.svg > /dev/null || fail "no figures"
  python3 "$check" F
  # nothing is played: a comparison missing from the caches is an error
  cp -r "$fixture" G
  sed -i '$d' G/runs/fixed-5-1/compare-cache.csv
  expect_bad "not in the caches" experiment report G
  # a plot that fails loses no table
  rm -rf G && cp -r "$fixture" G && rm G/report/*
  rc=0
  DUEL_PLOT_SCRIPT=/nonexistent/plot.py "$duel" experiment report G 2> plot.err || rc=$?
  [ "$rc" -eq 1 ] || fail "a failed plot: exit $rc"
  grep -q "the figures were not drawn" plot.err || fail "a failed plot: $(cat plot.err)"
  for f in table1.md table1.csv table1.json runs.csv fig7-complexity.csv fig11-levels.csv; do
    cmp "want/$f" "G/report/$f" || fail "a failed plot lost $f"
  done
  echo "report: ok"
  ;;
*)
  fail "mode $mode"
  ;;
esac
