#!/bin/sh
# mpi_bench.sh - a paper-scale run (configs/paper.ini) as one process on 2 threads against 2 MPI ranks of 1 thread on this machine, interleaved, with the messages and bytes a generation sends (docs/cluster.md).
# usage: bench/mpi_bench.sh [BUILD_DIR] [GENERATIONS] [REPEATS]; the last line is JSON.
set -eu
build=${1:-build}
gens=${2:-20}
reps=${3:-2}
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d /tmp/mpi_bench.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
mpi="mpirun --oversubscribe --mca pml ob1 --mca btl self,vader,tcp --mca btl_tcp_if_include lo --mca oob_tcp_if_include lo"
[ "$(id -u)" -ne 0 ] || mpi="$mpi --allow-run-as-root"
duel="$build/bin/duel_evolve"
# one measurement: MODE REP -> seconds per generation (mean of the run's own per-generation seconds) and CPU seconds
one() {
  dir="$tmp/$1-$2"
  case $1 in
    proc) set -- /usr/bin/time -f "%U %S" -o "$dir.cpu" "$duel" run --config "$root/configs/paper.ini" --out "$dir" \
            --generations "$gens" --threads 2 --quiet --json ;;
    ranks) set -- /usr/bin/time -f "%U %S" -o "$dir.cpu" $mpi -np 2 "$duel" run --config "$root/configs/paper.ini" \
             --out "$dir" --generations "$gens" --threads 1 --quiet --json ;;
  esac
  "$@" > "$dir.json"
  awk -F'"seconds":' '{ split($2, a, ","); s += a[1]; n++ } END { printf "%.4f", s / n }' "$dir.json"
  awk '{ printf " %.2f\n", $1 + $2 }' "$dir.cpu"
}
: > "$tmp/proc.txt"
: > "$tmp/ranks.txt"
r=1
while [ "$r" -le "$reps" ]; do
  one proc "$r" >> "$tmp/proc.txt"
  one ranks "$r" >> "$tmp/ranks.txt"
  r=$((r + 1))
done
same=true
r=1
while [ "$r" -le "$reps" ]; do
  cmp -s "$tmp/proc-1/checkpoint.bin" "$tmp/ranks-$r/checkpoint.bin" || same=false
  r=$((r + 1))
done
mean() { awk -v c="$2" '{ s += $c; n++ } END { printf "%.3f", s / n }' "$1"; }
p=$(mean "$tmp/proc.txt" 1); q=$(mean "$tmp/ranks.txt" 1)
pc=$(mean "$tmp/proc.txt" 2); qc=$(mean "$tmp/ranks.txt" 2)
# rank 0's counters for the whole run (log.txt): "games sent in M messages of B bytes, results in M2 of B2 bytes, over K batches"
line=$(grep "mpi: 2 MPI ranks" "$tmp/ranks-1/log.txt" | sed 's/.*games sent in //')
set -- $(echo "$line" | sed 's/[^0-9 ]//g')
echo "paper scale (configs/paper.ini), generations 0-$((gens - 1)), $reps interleaved repeats on $(nproc) cores"
echo "one process, 2 threads:   $p s per generation ($(tr '\n' ' ' < "$tmp/proc.txt")); CPU $pc s a run"
echo "2 MPI ranks x 1 thread:   $q s per generation ($(tr '\n' ' ' < "$tmp/ranks.txt")); CPU $qc s a run"
awk -v a="$p" -v b="$q" 'BEGIN { printf "2 ranks / 1 process: %.3f of the time\n", b / a }'
echo "identical runs: $same"
awk -v m="$1" -v b="$2" -v m2="$3" -v b2="$4" -v k="$5" -v g="$gens" 'BEGIN {
  printf "per generation, rank 0 sent %.1f messages of %.0f bytes and received %.1f of %.0f bytes, in %.1f batches\n",
         m / g, b / g, m2 / g, b2 / g, k / g }'
awk -v a="$p" -v b="$q" -v m="$1" -v bb="$2" -v m2="$3" -v b2="$4" -v k="$5" -v g="$gens" -v same="$same" 'BEGIN {
  printf "{\"generations\":%d,\"s_per_gen_process\":%.4f,\"s_per_gen_2ranks\":%.4f,\"ratio\":%.4f,\"identical\":%s,", g, a, b, b / a, same
  printf "\"sent_msgs_per_gen\":%.2f,\"sent_bytes_per_gen\":%.0f,\"recv_msgs_per_gen\":%.2f,\"recv_bytes_per_gen\":%.0f,\"batches_per_gen\":%.2f}\n",
         m / g, bb / g, m2 / g, b2 / g, k / g }'
