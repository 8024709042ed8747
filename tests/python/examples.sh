#!/usr/bin/env bash
# examples.sh PYTHON SRC - every example of examples/python/ runs to its end at a small size, in a directory of its
# own, and writes what it says it writes.
set -euo pipefail
py=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
fail() { echo "FAIL: $*" >&2; exit 1; }
ex=$src/examples/python
"$py" "$ex/xor.py" --out xor > xor.log || fail "xor.py: $(tail -3 xor.log)"
for f in champion.genome champion.blob champion.dot; do [ -s "xor/$f" ] || fail "xor.py wrote no $f"; done
grep -q "^solved after" xor.log || fail "xor.py: $(tail -1 xor.log)"
"$py" "$ex/cartpole.py" --generations 3 > cartpole.log || fail "cartpole.py: $(tail -3 cartpole.log)"
grep -q "the champion's mean return on 10 new episodes" cartpole.log || fail "cartpole.py: $(tail -1 cartpole.log)"
"$py" "$ex/race_to_ten.py" --generations 8 > race.log || fail "race_to_ten.py: $(tail -3 race.log)"
grep -q "dominant strategies; the top one" race.log || fail "race_to_ten.py: $(tail -1 race.log)"
"$py" "$ex/robot_duel.py" --generations 3 --set pop_size=16 --threads 2 --out duel.png > duel.log ||
  fail "robot_duel.py: $(tail -3 duel.log)"
[ "$(head -c 8 duel.png | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "robot_duel.py: duel.png is no PNG"
"$py" "$ex/run_reporters.py" --set pop_size=16 --set generations=40 --levels 3 --threads 2 --out rr > rr.log ||
  fail "run_reporters.py: $(tail -3 rr.log)"
grep -q "^3 levels at generation" rr.log || fail "run_reporters.py did not stop at 3 levels: $(tail -3 rr.log)"
grep -q "^generation [0-9]*: dominant 3 " rr.log || fail "run_reporters.py: no reporter line: $(cat rr.log)"
[ -f rr/checkpoint.bin ] && [ ! -e rr/checkpoint.bin.tmp ] || fail "run_reporters.py: no run directory"
"$py" -c "from neat_duel import runs; import sys; r = runs.resume('rr'); sys.exit(r.checkpoint().generation != 40)" ||
  fail "the example's run did not resume to its end"
echo "examples: ok"
