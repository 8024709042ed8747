#!/usr/bin/env bash
# fuzz.sh SECONDS [FUZZ_BUILD_DIR] - every libFuzzer harness for SECONDS each on a copy of its seed corpus; prints each
# one's executions, coverage and crashes and exits 1 on the first crash (its input is kept in build-fuzz/crashes/).
set -euo pipefail
secs=${1:?usage: scripts/fuzz.sh SECONDS [FUZZ_BUILD_DIR]}
root=$(cd "$(dirname "$0")/.." && pwd)
fuzz=$(realpath "${2:-$root/build-fuzz}")
crashes=$fuzz/crashes
mkdir -p "$crashes"
status=0
printf '%-14s %10s %8s %8s %s\n' harness execs cov ft result
for h in blob pop coev ini lcm_log lcm_msg rundir; do
  corpus=$(mktemp -d)
  cp "$root/tests/fuzz/corpus/$h/"* "$corpus"/
  rc=0
  # -timeout: an input that takes 10 s is a hang (an epoch that never ends); -rss_limit_mb: 2 GB;
  # -close_fd_mask=3: what the code under test prints is dropped, libFuzzer's and the sanitizers' reports are kept
  "$fuzz/tests/fuzz_$h" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -close_fd_mask=3 \
    -artifact_prefix="$crashes/$h-" "$corpus" > "$fuzz/fuzz_$h.log" 2>&1 || rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$fuzz/fuzz_$h.log" | tail -1)
  cov=$({ grep -o 'cov: [0-9]*' "$fuzz/fuzz_$h.log" || true; } | tail -1 | cut -d' ' -f2)
  ft=$({ grep -o 'ft: [0-9]*' "$fuzz/fuzz_$h.log" || true; } | tail -1 | cut -d' ' -f2)
  if [ "$rc" -eq 0 ]; then result="0 crashes"; else result="FAILED (exit $rc): see $fuzz/fuzz_$h.log"; status=1; fi
  printf '%-14s %10s %8s %8s %s\n' "$h" "${execs:-?}" "${cov:-?}" "${ft:-?}" "$result"
  [ "$rc" -eq 0 ] || grep -m3 -E "ERROR|SUMMARY|ALARM|deadly" "$fuzz/fuzz_$h.log" || true
  rm -rf "$corpus"
done
exit $status
