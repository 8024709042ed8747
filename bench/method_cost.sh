#!/bin/sh
# method_cost.sh - seconds per generation of each method of the paper's plan at the paper's scale (2 x 256), from
# its first GENERATIONS generations on THREADS threads: what docs/experiment.md's cost of the whole plan is
# built from. A best-topology run is measured when BLOB (a champion) is given.
# usage: bench/method_cost.sh [BUILD_DIR] [GENERATIONS] [THREADS] [BLOB]; one line per method, then JSON.
set -eu
build=${1:-build}
gens=${2:-20}
threads=${3:-2}
blob=${4:-}
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d /tmp/method_cost.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
json=""
for m in paper fixed-10 fixed-5 simplifying random-fitness best-topology; do
  set --
  if [ "$m" = best-topology ]; then
    [ -n "$blob" ] || continue
    set -- --set "start=blob:$blob"
  fi
  "$build/bin/duel_evolve" run --config "$root/configs/$m.ini" "$@" --out "$tmp/$m" --generations "$gens" \
    --threads "$threads" --quiet --json > "$tmp/$m.json"
  s=$(awk -F'"seconds":' '{ split($2, a, ","); s += a[1]; n++ } END { printf "%.4f", s / n }' "$tmp/$m.json")
  c=$(tail -1 "$tmp/$m/generations.csv" | cut -d, -f8)
  echo "$m: $s s per generation over generations 0-$((gens - 1)) ($threads threads; mean connections at the end $c)"
  json="$json${json:+,}\"$m\":$s"
done
echo "{\"generations\":$gens,\"threads\":$threads,\"s_per_gen\":{$json}}"
