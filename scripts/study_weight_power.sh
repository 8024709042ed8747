#!/usr/bin/env bash
# study_weight_power.sh OUT [SEEDS] [THREADS] [-- RUN_OPTION...] - the weight-perturbation study of docs/parameters.md:
# complexifying runs of configs/quick.ini with weight_perturb_power = weight_replace_range = 0.5, 1.0, 1.5, 2.5 and
# seeds 1..SEEDS (3), then every run's highest dominant against the dominance rankings of all the others (duel_evolve
# compare). RUN_OPTIONs go to every `duel_evolve run` (a smaller study: --set pop_size=32 --generations 50).
# Resumable: a finished run is kept, an unfinished one resumed, comparisons come from their cache.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
usage="usage: study_weight_power.sh OUT [SEEDS] [THREADS] [-- RUN_OPTION...]"
out=${1:?$usage}
shift
seeds=3 threads=0
if [ $# -gt 0 ] && [ "$1" != -- ]; then seeds=$1 && shift; fi
if [ $# -gt 0 ] && [ "$1" != -- ]; then threads=$1 && shift; fi
if [ $# -gt 0 ]; then
  [ "$1" = -- ] || { echo "$usage" >&2; exit 2; }
  shift
fi
duel=${DUEL_EVOLVE:-$root/build/bin/duel_evolve}
powers="0.5 1.0 1.5 2.5"
mkdir -p "$out"
all=()
for p in $powers; do
  for s in $(seq 1 "$seeds"); do
    d=$out/power-$p-seed-$s
    all+=("$d")
    if [ -f "$d/checkpoint.bin" ]; then
      "$duel" resume "$d" --threads "$threads" --quiet
    else
      "$duel" run --config "$root/configs/quick.ini" --set weight_perturb_power="$p" --set weight_replace_range="$p" \
        --seed "$s" --threads "$threads" --out "$d" --quiet "$@"
    fi
    echo "$(date -u +%FT%TZ) $d: $(tail -n 1 "$d/log.txt" | cut -d' ' -f2-)"
  done
done
for p in $powers; do
  "$duel" compare "$out"/power-"$p"-seed-* --against "${all[@]}" --threads "$threads" \
    --json "$out/compare-$p.json" --csv "$out/compare-$p.csv" > "$out/compare-$p.txt"
  cat "$out/compare-$p.txt"
done
