#!/usr/bin/env bash
# engine_same.sh - one run engine under three callers: duel_evolve run, the C example on libduelengine
# (examples/run_engine) and neat_duel.runs make the same run directory from one configuration, byte for byte
# (generations.csv but for its wall-time column, log.txt apart), and each resumes the others' runs to the same bytes.
#   engine_same.sh DUEL_EVOLVE RUN_ENGINE PYTHON CONFIG   (PYTHONPATH: the package)
set -euo pipefail
duel=$1 example=$2 py=$3 cfg=$4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
# every file of the two runs, generations.csv without its last column (seconds), log.txt (timestamps) apart
same() {
  local f
  [[ $(cd "$1" && find . -type f ! -name log.txt ! -name .lock | sort) == $(cd "$2" && find . -type f ! -name log.txt ! -name .lock | sort) ]] ||
    fail "$1 and $2 hold other files: $(cd "$1" && find . -type f | sort | tr '\n' ' ') / $(cd "$2" && find . -type f | sort | tr '\n' ' ')"
  for f in $(cd "$1" && find . -type f ! -name log.txt ! -name .lock ! -name generations.csv); do
    cmp -s "$1/$f" "$2/$f" || fail "$1 and $2 differ in $f"
  done
  cmp -s <(cut -d, -f1-16 "$1/generations.csv") <(cut -d, -f1-16 "$2/generations.csv") || fail "generations.csv differs"
}
"$duel" config --dump --config "$cfg" --set generations=5 --set strength_every=2 > "$tmp/small.ini"
"$duel" run --config "$tmp/small.ini" --out "$tmp/cli" --quiet --threads 2
out=$("$example" "$tmp/small.ini" "$tmp/c")
[[ $(grep -c '^generation [0-9]* of 5: ' <<< "$out") == 5 ]] || fail "the example's lines: $out"
[[ $(grep -c '^4,B,' <<< "$out") == 1 ]] || fail "the example's rows: $out"
"$py" -c "import sys; from neat_duel import runs; runs.run(sys.argv[1], sys.argv[2], threads=1)" "$tmp/small.ini" "$tmp/py"
same "$tmp/cli" "$tmp/c"
same "$tmp/cli" "$tmp/py"
echo "one run, three callers: the same files"
# each resumes another's run: the command resumes Python's, Python the command's and the example's
"$duel" resume "$tmp/py" --generations 8 --quiet
"$py" -c "import sys; from neat_duel import runs; [runs.resume(d, generations=8) for d in sys.argv[1:]]" "$tmp/cli" "$tmp/c"
same "$tmp/cli" "$tmp/py"
same "$tmp/cli" "$tmp/c"
# the example refuses what the command refuses, with the engine's line
if "$example" "$tmp/small.ini" "$tmp/cli" 2> "$tmp/err"; then fail "the example ran over a run"; fi
grep -q "^run_engine: .* already holds a run" "$tmp/err" || fail "the example's refusal: $(cat "$tmp/err")"
echo "resumed across callers: the same files"
# docs/library.md shows the example as it is
src=$(cd "$(dirname "$0")/../.." && pwd)
awk '/^<!-- examples\/run_engine\/run_engine.c -->$/ {on = 1; getline; next} on && /^```$/ {exit} on {print}' \
  "$src/docs/library.md" > "$tmp/doc.c"
cmp -s "$tmp/doc.c" "$src/examples/run_engine/run_engine.c" || fail "docs/library.md's run_engine.c is not examples/run_engine/run_engine.c"
echo "docs/library.md's example is the file"
