#!/bin/sh
# generation_cost.sh - seconds of one generation resumed from each run-directory snapshot, with two builds in
# turn (1 thread): how docs/experiment.md prices a whole run of the code before issue 16, from a sample of its
# generations, where playing the whole plan with that code does not fit a session. A snapshot is a copy of a
# run directory (taken while the run ran, e.g. at every 25th generation); each build resumes its own copy of it
# for exactly the generation its checkpoint holds next, so both play the same games (the results do not
# depend on the build).
# usage: bench/generation_cost.sh BUILD_A BUILD_B SNAPSHOT...
# one line per snapshot: snapshot, generation, seconds with A, seconds with B (the generation's own seconds,
# as generations.csv and report/timing.csv count them).
set -eu
[ $# -ge 3 ] || { echo "usage: bench/generation_cost.sh BUILD_A BUILD_B SNAPSHOT..." >&2; exit 2; }
a=$1
b=$2
shift 2
tmp=$(mktemp -d /tmp/generation_cost.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
# the seconds of the one generation BUILD plays from SNAPSHOT's checkpoint (next generation G: until G + 1)
one() {
  rm -rf "$tmp/run"
  cp -a "$2" "$tmp/run"
  ev="$1/bin/duel_evolve"
  # ending before the run's own last generation needs --shorten, where the build has it (builds
  # before that option shortened a run without it); a snapshot of a shorter run is extended instead
  short=""
  planned=$(sed -n 's/^generations *= *\([0-9]*\).*/\1/p' "$tmp/run/config.ini" | head -1)
  if [ "$(($3 + 1))" -lt "${planned:-0}" ] && "$ev" resume --help 2>&1 | grep -q -- --shorten; then
    short=--shorten
  fi
  "$ev" resume "$tmp/run" --generations "$(($3 + 1))" $short --threads 1 --quiet --json > "$tmp/out.json"
  awk -F'"seconds":' 'NF > 1 { split($2, s, /[,}]/); v = s[1] } END { if (v == "") exit 1; print v }' "$tmp/out.json"
}
echo "snapshot,generation,seconds_a,seconds_b"
for snap in "$@"; do
  g=$("$b/bin/duel_evolve" inspect "$snap/checkpoint.bin" | sed -n 's/.*next generation \([0-9]*\).*/\1/p')
  [ -n "$g" ] || { echo "generation_cost.sh: $snap/checkpoint.bin: no generation" >&2; exit 1; }
  sa=$(one "$a" "$snap" "$g")
  sb=$(one "$b" "$snap" "$g")
  echo "$(basename "$snap"),$g,$sa,$sb"
done
