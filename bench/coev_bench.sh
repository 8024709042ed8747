#!/bin/sh
# coev_bench.sh - seconds per generation of the paper-scale coevolution (configs/paper.ini) with 1 and 2 threads, and the speedup.
# usage: bench/coev_bench.sh [BUILD_DIR] [GENERATIONS]; the last line is JSON.
set -eu
build=${1:-build}
gens=${2:-20}
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d /tmp/coev_bench.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
for t in 1 2; do
  "$build/bin/duel_evolve" run --config "$root/configs/paper.ini" --out "$tmp/t$t" --generations "$gens" \
    --threads "$t" --quiet --json > "$tmp/t$t.json"
  # mean of the per-generation "seconds" (the whole generation: games, comparisons, reproduction)
  awk -F'"seconds":' '{ split($2, a, ","); s += a[1]; n++ } END { printf "%.4f\n", s / n }' "$tmp/t$t.json" > "$tmp/t$t.mean"
  awk -F'"games":' '{ split($2, a, ","); g += a[1] } END { print g }' "$tmp/t$t.json" > "$tmp/t$t.games"
done
s1=$(cat "$tmp/t1.mean"); s2=$(cat "$tmp/t2.mean"); games=$(cat "$tmp/t2.games")
cmp -s "$tmp/t1/checkpoint.bin" "$tmp/t2/checkpoint.bin" && same=true || same=false
top=$(tail -1 "$tmp/t2/dominance.csv" | cut -d, -f1,4,5)
echo "paper scale (configs/paper.ini), generations 1-$gens, $games games per thread count"
echo "1 thread:  $s1 s per generation"
echo "2 threads: $s2 s per generation"
awk -v a="$s1" -v b="$s2" 'BEGIN { printf "speedup 1 -> 2 threads: %.2f\n", a / b }'
echo "runs identical: $same; dominance level, hidden, connections at the end: $top"
awk -v a="$s1" -v b="$s2" -v g="$gens" -v same="$same" 'BEGIN {
  printf "{\"generations\":%d,\"s_per_gen_1\":%.3f,\"s_per_gen_2\":%.3f,\"speedup\":%.3f,\"identical\":%s}\n", g, a, b, a / b, same }'
