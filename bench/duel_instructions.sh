#!/bin/sh
# duel_instructions.sh - instructions per robot-step of a duel with 39- and 202-connection networks (callgrind, load-independent),
# with the AVX2 sensing where the processor has it, then with the scalar one (duel_bench --scalar).
# usage: bench/duel_instructions.sh [BUILD_DIR] [GAMES]; prints the breakdown for each size and path, and a JSON line.
set -eu
build=${1:-build}
games=${2:-20}
command -v valgrind >/dev/null || { echo "duel_instructions: valgrind is not installed" >&2; exit 2; }
out=$(mktemp /tmp/duel_cg.XXXXXX)
trap 'rm -f "$out"' EXIT
json=""
for run in 39 202 39-scalar 202-scalar; do
  conns=${run%-scalar}
  mode=""
  [ "$run" = "$conns" ] || mode=--scalar
  line=$(valgrind --tool=callgrind --callgrind-out-file="$out" "$build/bin/duel_bench" $mode --callgrind "$games" --conns "$conns" 2>/dev/null)
  simd=$(echo "$line" | sed -n 's/.*"simd":\([01]\).*/\1/p')
  path=scalar
  [ "$simd" = 1 ] && path=AVX2
  steps=$(echo "$line" | sed -n 's/.*"robot_steps":\([0-9]*\).*/\1/p')
  sum=$(echo "$line" | sed -n 's/.*"checksum":"\([0-9a-f]*\)".*/\1/p')
  [ -n "$steps" ] || { echo "duel_instructions: duel_bench printed no robot_steps" >&2; exit 1; }
  # inclusive instruction counts of the game's parts: with debug information
  # callgrind_annotate also lists partial entries (code inlined from other files),
  # so the largest entry of each function is its whole
  callgrind_annotate --inclusive=yes "$out" 2>/dev/null | awk -v steps="$steps" -v conns="$conns" -v sum="$sum" -v js="$out.json" -v run="$run" -v path="$path" '
    function take(name,   n) {
        if ($0 !~ (":" name "( |$)")) return
        n = $1; gsub(",", "", n); n += 0
        if (n > v[name]) v[name] = n
    }
    { take("duel_play"); take("duel_sense"); take("duel_sense_both"); take("nrt_step"); take("nrt_dense_step"); take("nrt_dense_step2"); take("duel_move") }
    END {
        # with AVX2 duel_play senses both robots with duel_sense_both, else duel_sense twice, and steps
        # both networks with nrt_dense_step2 where both have a dense form (it calls nrt_dense_step for
        # larger ones: its inclusive count has theirs), one with nrt_dense_step, else with nrt_step
        play = v["duel_play"]; sense = path == "AVX2" ? v["duel_sense_both"] : v["duel_sense"]; move = v["duel_move"]
        dense = v["nrt_dense_step2"] > v["nrt_dense_step"] ? v["nrt_dense_step2"] : v["nrt_dense_step"]
        net = v["nrt_step"] + dense
        if (!play || !sense || !net || !move) { print "duel_instructions: a function is missing from the profile" > "/dev/stderr"; exit 1 }
        core = sense + net + move
        printf "%d-connection networks, %s sensing: %d robot-steps, results checksum %s\n", conns, path, steps, sum
        printf "  sensing  %7.0f instructions per robot-step\n", sense / steps
        printf "  network  %7.0f (%.1f per connection; %s)\n", net / steps, net / steps / conns,
               dense ? (v["nrt_step"] ? "dense and nrt_step" : (v["nrt_dense_step2"] ? "nrt_dense_step2" : "nrt_dense_step")) : "nrt_step"
        printf "  motion   %7.0f\n", move / steps
        printf "  sensing + network + motion %.0f; whole game loop (rules, eating, collision) %.0f\n", core / steps, play / steps
        printf "\"%s\":{\"sensing_path\":\"%s\",\"robot_steps\":%d,\"sensing\":%.0f,\"network\":%.0f,\"per_conn\":%.2f,\"motion\":%.0f,\"core\":%.0f,\"game\":%.0f,\"checksum\":\"%s\"}",
               run, path, steps, sense / steps, net / steps, net / steps / conns, move / steps, core / steps, play / steps, sum > js
    }'
  json="$json${json:+,}$(cat "$out.json")"
  rm -f "$out.json"
done
echo "{$json}"
