#!/usr/bin/env bash
# make_fixture.sh DUEL - writes tests/tools/fixtures/experiment-tiny again: the experiment of tiny-plan.ini,
# kept without what its report does not read (checkpoints, logs, locks, the champions of no dominance level,
# the pictures), for the tools/experiment_report test. Run it when a format or the report changes, and commit.
set -euo pipefail
duel=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
out=$here/fixtures/experiment-tiny
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$duel" experiment "$here/tiny-plan.ini" --out "$tmp/e" --quiet
cd "$tmp/e"
find . \( -name checkpoint.bin -o -name log.txt -o -name .lock -o -name '*.png' -o -name '*.svg' \) -delete
for r in runs/*; do
  keep=$(tail -n +2 "$r/dominance.csv" | cut -d, -f2 | xargs -I{} printf 'gen-%05d.blob\n' {})
  for b in "$r"/champions/*.blob; do
    grep -qx "$(basename "$b")" <<< "$keep" || rm "$b"
  done
done
rm -rf "$out"
mkdir -p "$(dirname "$out")"
cp -r "$tmp/e" "$out"
du -sh "$out"
