#!/usr/bin/env bash
# fuzz.sh SECONDS [FUZZ_BUILD_DIR [HARNESS...]] - every libFuzzer harness (or those named: blob pop genome coev ini lcm_log
# lcm_msg rundir mpi_wire rules html) for SECONDS each on a copy of its seed corpus; prints each one's executions, coverage and crashes,
# and exits 1 if any crashed, hung or leaked (the input is kept in FUZZ_BUILD_DIR/crashes/).
set -euo pipefail
secs=${1:?usage: scripts/fuzz.sh SECONDS [FUZZ_BUILD_DIR [HARNESS...]]}
root=$(cd "$(dirname "$0")/.." && pwd)
fuzz=$(realpath "${2:-$root/build-fuzz}")
shift $(( $# < 2 ? $# : 2 ))
harnesses=${*:-blob pop genome coev ini lcm_log lcm_msg rundir mpi_wire rules html}
crashes=$fuzz/crashes
mkdir -p "$crashes"
status=0
jobs=${FUZZ_JOBS:-$(nproc)} # harnesses side by side: each is one process on one core
fuzz_one() { # fuzz_one HARNESS: its line of the table into $fuzz/fuzz_HARNESS.line, exit status 1 if it failed
  local h=$1 corpus rc=0 corp execs cov ft result
  corpus=$(mktemp -d)
  cp "$root/tests/fuzz/corpus/$h/"* "$corpus"/
  # -timeout: an input that takes 10 s is a hang (an epoch that never ends); -rss_limit_mb: 2 GB;
  # -close_fd_mask=3: what the code under test prints is dropped, libFuzzer's and the sanitizers' reports are kept
  "$fuzz/tests/fuzz_$h" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -close_fd_mask=3 \
    -artifact_prefix="$crashes/$h-" "$corpus" > "$fuzz/fuzz_$h.log" 2>&1 || rc=$?
  corp=$(find "$corpus" -type f | wc -l)
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$fuzz/fuzz_$h.log" | tail -1)
  cov=$({ grep -o 'cov: [0-9]*' "$fuzz/fuzz_$h.log" || true; } | tail -1 | cut -d' ' -f2)
  ft=$({ grep -o 'ft: [0-9]*' "$fuzz/fuzz_$h.log" || true; } | tail -1 | cut -d' ' -f2)
  if [ "$rc" -eq 0 ]; then result="0 crashes"; else result="FAILED (exit $rc): see $fuzz/fuzz_$h.log"; fi
  { printf '%-9s %8s %12s %6s %6s %7s %s\n' "$h" "$secs" "${execs:-?}" "${cov:-?}" "${ft:-?}" "$corp" "$result"
    [ "$rc" -eq 0 ] || grep -m3 -E "ERROR|SUMMARY|ALARM|deadly" "$fuzz/fuzz_$h.log" || true; } > "$fuzz/fuzz_$h.line"
  rm -rf "$corpus"
  [ "$rc" -eq 0 ]
}
printf '%-9s %8s %12s %6s %6s %7s %s\n' harness seconds execs cov ft corpus result
running=0
for h in $harnesses; do
  if [ "$running" -ge "$jobs" ]; then
    wait -n || status=1
    running=$((running - 1))
  fi
  fuzz_one "$h" &
  running=$((running + 1))
done
while [ "$running" -gt 0 ]; do
  wait -n || status=1
  running=$((running - 1))
done
for h in $harnesses; do cat "$fuzz/fuzz_$h.line"; done
exit $status
