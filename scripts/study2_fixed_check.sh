#!/usr/bin/env bash
# study2_fixed_check.sh DUEL S0_DIR OUT - docs/study2.md §1, "Cells": the registered check that s0's fixed runs stand
# for s3, s4 and s6. Run 1 of fixed-10 and of fixed-5 of s0 (S0_DIR, an experiment directory) is played again from
# its own config.ini under each of the three settings those cells change (add_node_prob = 0.003,
# equal_fitness_rule = smaller, reenable_rule = neat-cpp), into OUT/METHOD-SETTING; each must give s0's
# dominance.csv and champion blobs byte for byte. Resumable (a finished run is not played again; a killed one is
# resumed). Prints one line per run; exit 0 when all six are identical, 1 when any differs, 2 on bad input.
set -euo pipefail
[ $# -eq 3 ] || { echo "usage: study2_fixed_check.sh DUEL S0_DIR OUT" >&2; exit 2; }
duel=$1 s0=$2 out=$3
mkdir -p "$out"
status=0
for method in fixed-10-1 fixed-5-1; do
  ref=$s0/runs/$method
  [ -f "$ref/dominance.csv" ] && [ -f "$ref/config.ini" ] || { echo "$ref: not a finished run of s0" >&2; exit 2; }
  for setting in add_node_prob=0.003 equal_fitness_rule=smaller reenable_rule=neat-cpp; do
    dir=$out/$method-${setting%%=*}
    if [ -f "$dir/checkpoint.bin" ]; then
      "$duel" resume "$dir" --threads 1 --quiet
    else
      "$duel" run --config "$ref/config.ini" --set "$setting" --out "$dir" --threads 1 --quiet
    fi
    same=yes
    cmp -s "$ref/dominance.csv" "$dir/dominance.csv" || same="no (dominance.csv)"
    for b in "$ref"/champions/*.blob; do
      [ "$same" = yes ] || break
      cmp -s "$b" "$dir/champions/$(basename "$b")" || same="no ($(basename "$b"))"
    done
    n=$(ls "$ref"/champions/*.blob | wc -l)
    [ "$(ls "$dir"/champions/*.blob | wc -l)" -eq "$n" ] || same="no (the number of champions)"
    echo "$method with $setting: identical to s0's: $same ($n champions, $(($(wc -l < "$ref/dominance.csv") - 1)) levels)"
    [ "$same" = yes ] || status=1
  done
done
exit $status
