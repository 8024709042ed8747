#!/usr/bin/env bash
# study_m1.sh [OUT [CELL...]] - docs/study.md, stage A (M1): in every cell (or those named), one population evolved
# directly against forager-hunter and against forager (configs/vs-forager-hunter.ini: quick.ini's parameters, 128
# networks, 100 generations, 48 games on 24 comparison layouts drawn per generation), seeds 1-5; then the last
# champion's 288-game comparison with its opponent, in the cell's world. Resumable: a run whose comparison is done is
# skipped (a run stopped midway resumes). One row a run in OUT/m1.csv (default runs/study); then the summary per cell
# and opponent (scripts/study_summary.py OUT/m1.csv).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
duel=${DUEL_EVOLVE:-$root/build/bin/duel_evolve}
out=${1:-runs/study}
shift || true
# cell: name, then its --set overrides (every other setting world v1's and quick.ini's); docs/study.md, Hypotheses
cells=(
  "v1|"
  "h1-reach300|food_range=300 robot_range=300"
  "h1-reach150|food_range=150 robot_range=150"
  "h2-scale600|energy_scale=600"
  "h2-scale1200|energy_scale=1200"
  "h3-food100|food_energy=100"
  "h3-food400|food_energy=400"
  "h3-start2400|start_energy=2400"
  "h4-training|opponents.games=training"
  "h5-propagate|net_step=propagate"
  "h6-power2.5|weight_perturb_power=2.5"
  "h6-pop256|pop_size=256"
  "h6-survival0.4|survival_fraction=0.4"
  "h7-addnode0.003|add_node_prob=0.003"
  "h7-excess0|excess_equal_prob=0"
)
want=" $* "
mkdir -p "$out"
# one writer of OUT at a time: two would play the same runs twice and write every row twice
exec 9> "$out/.study_m1.lock"
flock -n 9 || { echo "study_m1.sh: $out is in use by another study_m1.sh: wait for it, or choose another OUT" >&2; exit 2; }
csv=$out/m1.csv
[ -s "$csv" ] || echo "cell,opponent,seed,wins,losses,draws,timeouts,margin,champion_hidden,champion_connections,run_seconds" > "$csv"
for c in "${cells[@]}"; do
  name=${c%%|*} sets=${c#*|}
  [ $# -eq 0 ] || [[ $want == *" $name "* ]] || continue
  for opp in forager-hunter forager; do
    for seed in 1 2 3 4 5; do
      d=$out/$name/$opp-$seed
      # done: a whole row (11 fields, ending in a number and a newline); a cut row is not a finished run
      if grep -Eq "^$name,$opp,$seed,([^,]*,){7}[0-9.]+\$" "$csv"; then continue; fi
      if grep -q "^$name,$opp,$seed," "$csv"; then
        echo "study_m1.sh: $csv: the row of $name $opp seed $seed is cut short: delete it, then run this again" >&2
        exit 2
      fi
      args=(--set "opponents.play=builtin:$opp")
      for s in $sets; do args+=(--set "$s"); done
      t0=$(date +%s.%N)
      # never removed: a run that died before its first checkpoint is started over by duel_evolve run itself,
      # and anything else there is refused by it (docs/hardening.md)
      if [ -f "$d/checkpoint.bin" ]; then
        "$duel" resume "$d" --quiet
      else
        "$duel" run --config "$root/configs/vs-forager-hunter.ini" --out "$d" --seed "$seed" "${args[@]}" --quiet
      fi
      t1=$(date +%s.%N)
      j=$("$duel" play "$d/champions/gen-00099.blob" "builtin:$opp" --games 288 --json)
      w=$(echo "$j" | sed 's/.*"a_wins":\([0-9]*\).*/\1/') l=$(echo "$j" | sed 's/.*"b_wins":\([0-9]*\).*/\1/')
      dr=$(echo "$j" | sed 's/.*"draws":\([0-9]*\).*/\1/') to=$(echo "$j" | sed 's/.*"timeouts":\([0-9]*\).*/\1/')
      size=$(tail -1 "$d/generations.csv" | cut -d, -f8,9)
      echo "$name,$opp,$seed,$w,$l,$dr,$to,$((w - l)),$size,$(awk "BEGIN { printf \"%.1f\", $t1 - $t0 }")" >> "$csv"
      echo "$name $opp seed $seed: $w:$l ($dr draws, $to timeouts)"
    done
  done
done
python3 "$root/scripts/study_summary.py" "$csv"
