#!/usr/bin/env bash
# readme_commands.sh SOURCE BUILD [README] - every command block (```sh) of the README run as written, in order, in a directory laid out as a checkout after the README's set-up; long jobs at a reduced size (the table below): the README cannot drift from the tools.
set -euo pipefail
src=$(realpath "$1")
build=$(realpath "$2")
readme=$(realpath "${3:-$src/README.md}")
work=$(mktemp -d)
cleanup() {
  # whatever a block left running in the background (LCM's hub)
  pkill -f "lcm.lcm.TCPService 7700$" 2> /dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; exit 1; }

# The checkout's layout: every top-level entry of the source, the build directory as build/; runs/ and
# whatever the commands write are this directory's own.
for e in "$src"/*; do
  n=$(basename "$e")
  case "$n" in build | build-* | runs) ;; *) ln -s "$e" "$work/$n" ;; esac
done
ln -s "$build" "$work/build"

# Reductions: what a command becomes here (the rest runs as written).
# - the set-up: its main job, configs/quick.ini into runs/quick (as scripts/setup.sh runs it), small
#   populations and few opponents, every generation kept (later commands name its champions);
#   the test suite: not run (this test is part of it)
# - run: the same small populations and opponents, the generations as written (20 when no later command
#   names the run's champions)
# - experiment: the same, and 3 generations
# - mpirun: as root, allowed; on this machine (oversubscribed, shared memory and loopback); a hostfile's
#   cluster command is not run
# - benchmarks: 2 generations (coev_bench), 2 games (duel_instructions), 2 runs (neat_bench pole, pole-nv)
small="--set pop_size=8 --set species_opponents=1 --set hof_opponents=1 --set first_opponents=2 --set compare_configs=1"
reduce() { # reduce COMMAND: prints the command to run, or nothing to skip it
  local c=$1
  case "$c" in
  "./scripts/setup.sh"*)
    echo "build/bin/duel_evolve run --config configs/quick.ini --out runs/quick --quiet $small && build/bin/duel_evolve ladder runs/quick"
    return ;;
  "./scripts/test.sh"* | *"--hostfile"*) return ;;
  esac
  case "$c" in
  *"duel_evolve run "* | *"duel_evolve resume "*) c="$c --quiet" ;;
  esac
  case "$c" in
  *"duel_evolve run "*)
    c="$c $small"
    # a run whose champions no later command names: 20 generations
    local out
    out=$(printf '%s\n' "$c" | sed -n 's/.*--out \([^ ]*\).*/\1/p')
    grep -qF "$out/champions/" "$work/.commands" || c="$c --generations 20" ;;
  *"duel_evolve experiment configs/"*) c="$c --quiet $small --set generations=3" ;;
  "bench/coev_bench.sh"*) c="bench/coev_bench.sh build 2" ;;
  "bench/duel_instructions.sh"*) c="bench/duel_instructions.sh build 2" ;;
  *"neat_bench pole"*) c="$c --runs 2" ;;
  esac
  echo "$c"
}

# The blocks, a command per line (a line ending in \ continues), each with its comment cut off.
awk '/^```sh/ { inside = 1; n++; next } /^```/ { inside = 0; next }
     inside { if (cont != "") { $0 = cont " " $0; cont = "" }
              if ($0 ~ /\\$/) { sub(/\\$/, ""); cont = $0; next }
              print n "\t" $0 }' "$readme" > "$work/.commands"
[ -s "$work/.commands" ] || fail "no command blocks in $readme"

cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMPI_MCA_pml=ob1 OMPI_MCA_btl=self,vader,tcp OMPI_MCA_btl_tcp_if_include=lo OMPI_MCA_oob_tcp_if_include=lo
block=0 ran=0 skipped=0
pids=()
while IFS=$'\t' read -r b line; do
  if [ "$b" != "$block" ]; then
    # a block's background processes end with it
    for p in "${pids[@]}"; do kill "$p" 2> /dev/null || true; done
    pids=()
    block=$b
  fi
  cmd=$(printf '%s\n' "$line" | sed -E 's/[[:space:]]+#[[:space:]].*$//; s/[[:space:]]+$//')
  [ -n "$cmd" ] || continue
  run=$(reduce "$cmd")
  if [ -z "$run" ]; then
    echo "-- block $b: skipped: $cmd"
    skipped=$((skipped + 1))
    continue
  fi
  echo "-- block $b: $run"
  if [ "${run: -1}" = "&" ]; then
    bash -c "${run%&}" < /dev/null > "$work/.bg$ran.log" 2>&1 &
    pids+=($!)
    sleep 1 # a server started in the background gets its second before the next command
  else
    start=$(date +%s)
    bash -o pipefail -c "$run" < /dev/null > "$work/.out" 2>&1 || { tail -20 "$work/.out"; fail "block $b: '$run' failed"; }
    echo "   ok ($(($(date +%s) - start)) s)"
  fi
  ran=$((ran + 1))
done < "$work/.commands"
for p in "${pids[@]}"; do kill "$p" 2> /dev/null || true; done
echo "ok: $ran commands of $(basename "$readme") ran, $skipped skipped (the set-up's test suite, a cluster's hostfile)"
