#!/usr/bin/env bash
# readme_commands.sh SOURCE BUILD [MARKDOWN [SETUP]] - every command block (```sh) of the README, or of a doc, run as
# written, in order, in a directory laid out as a checkout; long jobs at a reduced size, what cannot run here skipped
# with its reason (the tables below): the README and the docs cannot drift from the tools.
#   readme_commands.sh SOURCE BUILD                  the README's blocks, its set-up (the first block) first
#   readme_commands.sh SOURCE BUILD DOC.md [SETUP]   the README's set-up, then DOC's blocks; with SETUP, the set-up's
#                                                    state is a copy of SETUP's (made by --setup) instead
#   readme_commands.sh SOURCE BUILD --setup SETUP    the README's set-up alone, its state left in SETUP (a new
#                                                    directory, or one an earlier --setup made)
set -euo pipefail
fail() { echo "FAIL: $*"; exit 1; }
[ $# -ge 2 ] || fail "usage: readme_commands.sh SOURCE BUILD [MARKDOWN [SETUP] | --setup SETUP]"
src=$(realpath "$1")
build=$(realpath "$2")
readme=$src/README.md
doc= setup= keep=
case "${3:-}" in
"") ;;
--setup) keep=${4:?--setup needs a directory} ;;
*)
  doc=$(realpath "$3")
  [ "$doc" != "$readme" ] || doc=
  setup=${4:-}
  [ -z "$setup" ] || [ -e "$setup/.readme_setup_done" ] || fail "$setup: no set-up state (readme_commands.sh --setup makes it)"
  ;;
esac

if [ -n "$keep" ]; then
  if [ -e "$keep" ]; then
    [ -e "$keep/.readme_setup" ] || fail "$keep exists and was not made by readme_commands.sh --setup"
    rm -rf "$keep"
  fi
  mkdir -p "$keep"
  touch "$keep/.readme_setup"
  work=$(realpath "$keep")
else
  work=$(mktemp -d)
fi
pids=() # the process groups of the commands started in the background (LCM's hub, the nodes)
stop_background() {
  for p in "${pids[@]}"; do kill -- "-$p" 2> /dev/null || kill "$p" 2> /dev/null || true; done
  pids=()
}
cleanup() {
  stop_background
  [ -n "$keep" ] || rm -rf "$work"
}
trap cleanup EXIT

# The checkout's layout: every top-level entry of the source, the build directory as build/; runs/ and
# whatever the commands write are this directory's own (with SETUP: a copy of the set-up's).
for e in "$src"/*; do
  n=$(basename "$e")
  case "$n" in build | build-* | runs) ;; *) ln -s "$e" "$work/$n" ;; esac
done
ln -s "$build" "$work/build"
if [ -n "$setup" ]; then
  find "$setup" -mindepth 1 -maxdepth 1 ! -type l ! -name '.*' -exec cp -a {} "$work"/ \;
fi

# Not run here (skip prints why): the set-up's test suite (this test is part of it), a cluster's commands.
skip() {
  case "$1" in
  "./scripts/test.sh"*) echo "the whole test suite: this test is part of it" ;;
  *"--hostfile"*) echo "a hostfile names a cluster's machines: there is none here" ;;
  "sbatch "*) echo "a Slurm cluster: there is none here" ;;
  "git clone . /tmp/a"* | "(cd /tmp/a && CI=true bash .ci/run"*) echo "two whole test suites at once: this test is part of one" ;;
  "python3 -m venv .venv"* | ".venv/bin/"*)
    echo "the Python package's installation: CTest python/install builds and installs it as pip does" ;;
  "PYTHONPATH=build/python "*) [ -d "$build/python/neat_duel" ] || echo "this build has no Python package (NEAT_PYTHON=OFF)" ;;
  esac
}
# Reductions: what a command becomes here (the rest, and every command of several lines (a loop, a here-document),
# runs as written).
# - the set-up: its main job, configs/quick.ini into runs/quick (as scripts/setup.sh runs it), small
#   populations and few opponents, every generation kept (later commands name its champions)
# - run: the same small populations and opponents, the generations as written (20 when no later command
#   names the run's champions)
# - experiment: the same, and 3 generations
# - the weight-perturbation study (docs/parameters.md): its runs as small as run's, 20 generations
# - mpirun: as root, allowed; on this machine (oversubscribed, shared memory and loopback: the
#   environment below)
# - benchmarks: 2 generations (coev_bench), 2 games (duel_instructions), 2 runs (neat_bench pole, pole-nv),
#   this build in place of the older one (generation_cost: there is no other build here)
small="--set pop_size=8 --set species_opponents=1 --set hof_opponents=1 --set first_opponents=2 --set compare_configs=1"
reduce() { # reduce COMMAND: prints the command to run
  local c=$1
  case "$c" in
  *$'\n'*) echo "$c"; return ;;
  "./scripts/setup.sh"*)
    echo "build/bin/duel_evolve run --config configs/quick.ini --out runs/quick --quiet $small && build/bin/duel_evolve ladder runs/quick"
    return ;;
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
  "scripts/study_weight_power.sh"*) c="$c 0 -- $small --generations 20" ;;
  "bench/coev_bench.sh"*) c="bench/coev_bench.sh build 2" ;;
  "bench/duel_instructions.sh"*) c="bench/duel_instructions.sh build 2" ;;
  "bench/generation_cost.sh "*) c=${c#bench/generation_cost.sh }; c="bench/generation_cost.sh build ${c#* }" ;;
  *"neat_bench pole"*) c="$c --runs 2" ;;
  *"bench/python_xor.py"*) c="${c/--rounds 9/--rounds 1}" ;;
  *"bench/python_envs.py"*) c="${c/--rounds 5/--rounds 1}" ;;
  esac
  echo "$c"
}

# commands FILE LABEL [BLOCKS]: the commands of FILE's ```sh blocks (only the first BLOCKS of them), one a line:
# "LABEL N<tab>COMMAND" for block N. Comments are cut, a line ending in \ goes on in the next one, and a command
# of several lines (a loop, a here-document, whose lines stay as written) has them joined by \x1f.
commands() {
  local file=$1 label=$2 most=${3:-0} n=0 inside=0 cmd= sep= eof= line
  local heredoc="<<-?[[:space:]]*['\"]?([A-Za-z_][A-Za-z0-9_]*)"
  while IFS= read -r line || [ -n "$line" ]; do
    if [ "$inside" = 0 ]; then
      if [ "$line" = '```sh' ]; then
        n=$((n + 1))
        [ "$most" = 0 ] || [ "$n" -le "$most" ] || break
        inside=1
      fi
      continue
    fi
    if [ -n "$eof" ]; then
      cmd+=$'\n'$line
      [ "$line" = "$eof" ] || continue
      eof=
    else
      if [[ $line == '```'* ]]; then
        [ -z "$cmd" ] || fail "$file: block $n ends inside a command: $cmd"
        inside=0
        continue
      fi
      [[ ! $line =~ ^[[:space:]]*# ]] || line=
      line=${line%%[[:space:]]#[[:space:]]*}
      line=${line%"${line##*[![:space:]]}"}
      [ -n "$cmd$line" ] || continue
      cmd+=$sep$line
      if [[ $cmd == *\\ ]]; then
        cmd=${cmd%\\} sep=' '
        continue
      fi
      sep=$'\n'
      if [[ $line =~ $heredoc ]]; then
        eof=${BASH_REMATCH[1]}
        continue
      fi
      bash -n -c "$cmd" 2> /dev/null || continue # a loop or an if that goes on
    fi
    printf '%s %s\t%s\n' "$label" "$n" "${cmd//$'\n'/$'\x1f'}"
    cmd= sep=
  done < "$file"
  [ "$inside" = 0 ] || [ "$most" != 0 ] || fail "$file: block $n is not closed"
}

# What runs: the README's blocks, its set-up first; or the README's set-up (unless SETUP has its state), then the doc's.
if [ -z "$doc" ] && [ -z "$keep" ]; then
  commands "$readme" "README block" > "$work/.commands"
elif [ -z "$setup" ]; then
  commands "$readme" "README block" 1 > "$work/.commands"
else
  : > "$work/.commands"
  echo "-- the README's set-up: its state as left in $setup"
fi
[ -n "$setup" ] || grep -q "^README block 1"$'\t'"./scripts/setup.sh" "$work/.commands" ||
  fail "the README's first command block is not its set-up (./scripts/setup.sh)"
if [ -n "$doc" ]; then
  commands "$doc" "docs/$(basename "$doc") block" > "$work/.doc"
  [ -s "$work/.doc" ] || fail "no command blocks in $doc"
  cat "$work/.doc" >> "$work/.commands"
fi

cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMPI_MCA_pml=ob1 OMPI_MCA_btl=self,vader,tcp OMPI_MCA_btl_tcp_if_include=lo OMPI_MCA_oob_tcp_if_include=lo
block= ran=0 skipped=0 reasons= doc_port=
# shellcheck source=/dev/null
. "$src/tests/lcm/lcm_hub.sh"
while IFS=$'\t' read -r b cmd; do
  # a block's background processes end with it
  [ "$b" = "$block" ] || stop_background
  block=$b
  cmd=${cmd//$'\x1f'/$'\n'}
  why=$(skip "$cmd")
  if [ -n "$why" ]; then
    echo "-- $b: skipped ($why): $cmd"
    skipped=$((skipped + 1))
    case "$reasons" in *"$why"*) ;; *) reasons+="${reasons:+; }$why" ;; esac
    continue
  fi
  run=$(reduce "$cmd")
  # LCM's hub: never the doc's port (another suite, or anything else, may hold it: issue 42), but a free one this
  # test's own hub is seen listening on; every later command of the doc gets that port in place of the doc's
  if [[ $run =~ ^java\ -cp\ ([^ ]+)\ lcm\.lcm\.TCPService\ ([0-9]+)\ *\&$ ]]; then
    doc_port=${BASH_REMATCH[2]}
    lcm_hub_start java "${BASH_REMATCH[1]}" "$work/.hub" ||
      fail "$b: LCM's hub did not start: $lcm_hub_error"
    pids+=("$lcm_hub_pid")
    echo "-- $b: $run (the hub on free port $lcm_hub_port, standing for $doc_port)"
    ran=$((ran + 1))
    continue
  fi
  [ -z "$doc_port" ] || run=${run//127.0.0.1:$doc_port/127.0.0.1:$lcm_hub_port}
  echo "-- $b: $run"
  if [ "${run: -1}" = "&" ]; then
    # in a process group of its own, which ends with the block
    setsid bash -c "${run%&}" < /dev/null > "$work/.bg$ran.log" 2>&1 &
    pids+=($!)
    sleep 1 # a server started in the background gets its second before the next command
  else
    start=$(date +%s)
    bash -e -o pipefail -c "$run" < /dev/null > "$work/.out" 2>&1 || { tail -20 "$work/.out"; fail "$b: '$run' failed"; }
    echo "   ok ($(($(date +%s) - start)) s)"
  fi
  ran=$((ran + 1))
done < "$work/.commands"
stop_background
[ -z "$keep" ] || touch "$work/.readme_setup_done"
echo "ok: $ran commands of $(basename "${doc:-$readme}") ran, $skipped skipped${reasons:+ ($reasons)}"
