#!/usr/bin/env bash
# fuzz_corpus.sh [BUILD_DIR] [FUZZ_BUILD_DIR] - (re)makes the fuzzers' seed corpora in tests/fuzz/corpus/NAME with the
# project's own tools: blobs and population checkpoints (make_corpus), a small coevolution's checkpoint, config and
# CSVs (duel_evolve run, compare), INI files (configs/, bench/), LCM logs cut short and crafted ones, LCM messages.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(realpath "${1:-$root/build}")
fuzz=$(realpath "${2:-$root/build-fuzz}")
c=$root/tests/fuzz/corpus
duel=$build/bin/duel_evolve
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# inputs that once crashed a harness (regress-*) are kept, and checkpoints of version 2 (v2-*), which still load
# but which nothing writes any more
for d in blob pop genome coev ini lcm_log lcm_msg rundir html; do
  mkdir -p "$c/$d"
  find "$c/$d" -type f ! -name 'regress-*' ! -name 'v2-*' -delete
done

"$fuzz/tests/make_corpus" "$c/blob" "$c/pop" > /dev/null

# a coevolution small enough to mutate quickly: 2 x 6 genomes, 2 food configurations
printf '[run]\ngenerations = 3\nseed = 3\n[coevolution]\nspecies_opponents = 1\nhof_opponents = 2\nfirst_opponents = 2\ncompare_configs = 2\n[neat]\npop_size = 6\nadd_node_prob = 0.3\nadd_conn_prob = 0.3\n' > "$work/tiny.ini"
"$duel" run --config "$work/tiny.ini" --out "$work/r1" --generations 1 --quiet
"$duel" run --config "$work/tiny.ini" --out "$work/r3" --quiet
cp "$work/r1/checkpoint.bin" "$c/coev/gen1.bin"
cp "$work/r3/checkpoint.bin" "$c/coev/gen3.bin"
# the same under NEAT C++ 1.2.1's profile: its populations' checkpoints are version 4
"$duel" run --config "$work/tiny.ini" --out "$work/p3" --quiet --set profile=neat-cpp-1.2.1
cp "$work/p3/checkpoint.bin" "$c/coev/neat-cpp-gen3.bin"
cp "$work/r3/champions/"*.genome "$c/genome/"

cp "$root/configs/"*.ini "$root/bench/"*.ini "$root/tests/tools/coev-small.ini" "$c/ini/"
cp "$root/tests/tools/fixtures/world-variant.ini" "$c/ini/world-variant.ini"
"$duel" config --dump --config "$root/configs/vs-forager-hunter.ini" --set world.food_range=300 > "$c/ini/run-config-fixed.ini"
for p in "$root/configs/plans/"*.ini "$root/tests/tools/tiny-plan.ini"; do cp "$p" "$c/ini/plan-$(basename "$p")"; done
cp "$work/r3/config.ini" "$c/ini/run-config.ini"
printf 'pop_size=40\n[neat]\nc1 = 25e-1\r\n; comment\n# comment\n[run]\nseed = 3\n' > "$c/ini/set-and-syntax.ini"

"$duel" play builtin:forager-hunter builtin:idle --lcm-log "$work/g.lcm" > /dev/null
head -c 6000 "$work/g.lcm" > "$c/lcm_log/game-start.lcm"
tail -c 3000 "$work/g.lcm" > "$c/lcm_log/game-end-unsynced.lcm"
for name in motor-negative state-negative motor-no-nul state-huge; do
  "$build/tests/lcm_hostile" log "$name" "$c/lcm_log/$name.lcm"
done
"$build/tests/lcm_hostile" corpus "$c/lcm_msg"

cp "$work/r3/dominance.csv" "$c/rundir/dominance.csv"
cp "$work/r3/generations.csv" "$c/rundir/generations.csv"
"$duel" compare "$work/r3" --against "$work/r1" > /dev/null
cp "$work/r3/compare-cache.csv" "$c/rundir/compare-cache.csv"
printf 'generation,population\n0,A\n1,B\n2,A' > "$c/rundir/torn.csv"

# what the web pages show: a run's records, its ladder, and an experiment's tables (the committed tiny experiment)
"$duel" ladder "$work/r3" > /dev/null
for f in generations.csv config.ini ladder.csv; do cp "$work/r3/$f" "$c/html/$f"; done
cp "$root/tests/tools/fixtures/experiment-tiny/report/table1.csv" "$root/tests/tools/fixtures/experiment-tiny/report/runs.csv" "$c/html/"
du -sh "$c"/* | sed "s|$c/||"
