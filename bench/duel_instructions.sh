#!/bin/sh
# duel_instructions.sh - instructions per robot-step of a duel (callgrind, load-independent).
# usage: bench/duel_instructions.sh [BUILD_DIR] [GAMES]; prints the breakdown and a JSON line.
set -eu
build=${1:-build}
games=${2:-20}
command -v valgrind >/dev/null || { echo "duel_instructions: valgrind is not installed" >&2; exit 2; }
out=$(mktemp /tmp/duel_cg.XXXXXX)
trap 'rm -f "$out"' EXIT
steps=$(valgrind --tool=callgrind --callgrind-out-file="$out" "$build/bin/duel_bench" --callgrind "$games" 2>/dev/null |
        sed -n 's/.*"robot_steps":\([0-9]*\).*/\1/p')
[ -n "$steps" ] || { echo "duel_instructions: duel_bench printed no robot_steps" >&2; exit 1; }
# inclusive instruction counts of the game's parts: with debug information
# callgrind_annotate also lists partial entries (code inlined from other files),
# so the largest entry of each function is its whole
callgrind_annotate --inclusive=yes "$out" 2>/dev/null | awk -v steps="$steps" '
    function take(name,   n) {
        if ($0 !~ (":" name "( |$)")) return
        n = $1; gsub(",", "", n); n += 0
        if (n > v[name]) v[name] = n
    }
    { take("duel_play"); take("duel_sense"); take("nrt_step"); take("duel_move") }
    END {
        play = v["duel_play"]; sense = v["duel_sense"]; net = v["nrt_step"]; move = v["duel_move"]
        if (!play || !sense || !net || !move) { print "duel_instructions: a function is missing from the profile" > "/dev/stderr"; exit 1 }
        core = sense + net + move
        printf "robot-steps %d\n", steps
        printf "sensing  %7.0f instructions per robot-step\n", sense / steps
        printf "network  %7.0f\n", net / steps
        printf "motion   %7.0f\n", move / steps
        printf "sensing + network + motion %.0f; whole game loop (rules, eating, collision) %.0f\n", core / steps, play / steps
        printf "{\"robot_steps\":%d,\"sensing\":%.0f,\"network\":%.0f,\"motion\":%.0f,\"core\":%.0f,\"game\":%.0f}\n",
               steps, sense / steps, net / steps, move / steps, core / steps, play / steps
    }'
