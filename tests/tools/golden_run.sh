#!/usr/bin/env bash
# golden_run.sh DUEL_EVOLVE CONFIG SUMS [GENERATIONS] - a run of CONFIG with seed 7 on 2 threads gives, byte for byte,
# the files recorded in SUMS (sha256sum lines; generations.csv without its timing column): the speed-ups of the
# simulator and the runtime change no result. "record" as a fifth argument writes SUMS instead.
set -euo pipefail
duel=$1 cfg=$2 sums=$(realpath -m "$3") gens=${4:-6} mode=${5:-check}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$duel" run --config "$cfg" --seed 7 --generations "$gens" --threads 2 --out "$work/run" --quiet
cd "$work/run"
# the last column of generations.csv is the generation's wall time
sed 's/,[^,]*$//' generations.csv > generations-untimed.csv
sha256sum checkpoint.bin dominance.csv generations-untimed.csv champions/*.blob > "$work/got"
if [ "$mode" = record ]; then
  cp "$work/got" "$sums"
  echo "recorded $(wc -l < "$sums") files in $sums"
  exit 0
fi
if ! diff "$sums" "$work/got"; then
  echo "FAIL: the run's files differ from the recorded ones (above: < recorded, > now)"
  exit 1
fi
echo "ok: $(wc -l < "$sums") files identical to the recorded run"
