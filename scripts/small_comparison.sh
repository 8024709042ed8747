#!/usr/bin/env bash
# small_comparison.sh OUT [SEEDS] [THREADS] - the measured comparison of docs/experiment.md: SEEDS (3) runs each of
# complexifying (configs/paper.ini), fixed-topology 5 hidden (configs/fixed-5.ini) and simplifying
# (configs/simplifying.ini) coevolution at configs/quick.ini's scale (2 x 128 networks, 200 generations), then every
# method's highest dominants against the complexifying runs' dominance rankings (duel_evolve compare).
# Resumable: finished runs are kept, unfinished ones resumed, comparisons come from their caches.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:?usage: small_comparison.sh OUT [SEEDS] [THREADS]}
seeds=${2:-3}
threads=${3:-0}
duel=${DUEL_EVOLVE:-$root/build/bin/duel_evolve}
methods=${METHODS:-"complexify:paper fixed-5:fixed-5 simplify:simplifying"}
mkdir -p "$out"
start=$(date +%s)
for m in $methods; do
  name=${m%%:*}
  for s in $(seq 1 "$seeds"); do
    d=$out/$name-$s
    t0=$(date +%s)
    if [ -f "$d/checkpoint.bin" ]; then
      "$duel" resume "$d" --threads "$threads" --quiet
    else
      "$duel" run --config "$root/configs/${m#*:}.ini" --set pop_size=128 --generations 200 --seed "$s" \
        --threads "$threads" --out "$d" --quiet
    fi
    echo "$d: $(( $(date +%s) - t0 )) s: $(tail -n 1 "$d/log.txt" | cut -d' ' -f2-)"
  done
done
rankings=("$out"/complexify-*)
for m in $methods; do
  name=${m%%:*}
  echo "== $name against the complexifying rankings"
  "$duel" compare "$out/$name"-* --against "${rankings[@]}" --threads "$threads" --json "$out/compare-$name.json" \
    --csv "$out/compare-$name.csv"
done
echo "total: $(( $(date +%s) - start )) s"
