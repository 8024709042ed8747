#!/usr/bin/env bash
# small_comparison.sh OUT [SEEDS] [THREADS] - the measured comparison of docs/experiment.md: SEEDS (3) runs of each
# method of the paper's Table 1 at configs/quick.ini's scale (2 x 128 networks, 200 generations), then every method's
# highest dominants against the complexifying runs' dominance rankings (duel_evolve compare). The best-topology
# method starts from the complexifying champion with the highest cross-run performance ("highest" reading, then
# "contiguous", then the first), recorded in OUT/best-topology.txt. METHODS="name:preset ..." picks methods.
# Resumable: finished runs are kept, unfinished ones resumed, comparisons come from their caches.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:?usage: small_comparison.sh OUT [SEEDS] [THREADS]}
seeds=${2:-3}
threads=${3:-0}
duel=${DUEL_EVOLVE:-$root/build/bin/duel_evolve}
methods=${METHODS:-"complexify:paper fixed-10:fixed-10 fixed-5:fixed-5 best:best-topology simplify:simplifying random:random-fitness"}
mkdir -p "$out"
start=$(date +%s)

runs() { # runs NAME PRESET [--set ...]: SEEDS runs of a preset
  local name=$1 preset=$2 s d t0
  shift 2
  for s in $(seq 1 "$seeds"); do
    d=$out/$name-$s
    t0=$(date +%s)
    if [ -f "$d/checkpoint.bin" ]; then
      "$duel" resume "$d" --threads "$threads" --quiet
    else
      "$duel" run --config "$root/configs/$preset.ini" "$@" --set pop_size=128 --generations 200 --seed "$s" \
        --threads "$threads" --out "$d" --quiet
    fi
    echo "$d: $(( $(date +%s) - t0 )) s: $(tail -n 1 "$d/log.txt" | cut -d' ' -f2-)"
  done
}

runs complexify paper
rankings=("$out"/complexify-[0-9]*)
for m in $methods; do
  name=${m%%:*}
  preset=${m#*:}
  case $name in
  complexify) ;;
  best)
    "$duel" compare "${rankings[@]}" --against "${rankings[@]}" --threads "$threads" --json "$out/compare-complexify.json" \
      > /dev/null
    blob=$(python3 - "$out/compare-complexify.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
best = max(enumerate(d["candidates"]),
           key=lambda ic: (ic[1]["highest"]["performance"], ic[1]["contiguous"]["performance"], -ic[0]))[1]
print("%s/champions/gen-%05d.blob" % (best["run"], best["generation"]))
PY
)
    echo "the best complexifying champion: $blob" | tee "$out/best-topology.txt"
    runs best "$preset" --set "start=blob:$blob"
    ;;
  *) runs "$name" "$preset" ;;
  esac
done
for m in $methods; do
  name=${m%%:*}
  echo "== $name against the complexifying rankings"
  "$duel" compare "$out/$name"-[0-9]* --against "${rankings[@]}" --threads "$threads" --json "$out/compare-$name.json" \
    --csv "$out/compare-$name.csv"
done
echo "total: $(( $(date +%s) - start )) s"
