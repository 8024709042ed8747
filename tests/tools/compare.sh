#!/usr/bin/env bash
# compare.sh - duel_evolve compare against play --games 288 one comparison at a time, thread and cache independence, bad input.
set -euo pipefail
duel=$1
cfg=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=/dev/null
. "$(dirname "$0")/cli_lib.sh"

for s in 1 2 3; do
  "$duel" run --config "$cfg" --generations 12 --seed "$s" --out "$tmp/r$s" --quiet
done
cd "$tmp"
"$duel" compare r1 r2 r3 --against r1 r2 r3 --threads 1 --csv a.csv --json a.json > a.txt
grep -q "3 runs against the dominance rankings of 3 runs (never its own): 6 pairs" a.txt || fail "$(cat a.txt)"
[ "$(tail -n +2 a.csv | wc -l)" -eq 6 ] || fail "a.csv: $(cat a.csv)"
! grep -q '^r1,[^,]*,[^,]*,r1,' a.csv || fail "a run ranked against itself"
python3 -c 'import json,sys; d=json.load(open("a.json")); assert d["runs"] == 3 and len(d["candidates"]) == 3' ||
  fail "a.json is not the JSON expected"

# every comparison is what play --games 288 gives, one by one
n=0
while IFS=, read -r cand _ cgen rank levels _ _ _ _ _ _ wins _; do
  read -ra wl <<< "$wins"
  [ "${#wl[@]}" -eq "$levels" ] || fail "$cand vs $rank: ${#wl[@]} results for $levels levels"
  k=0
  while IFS=, read -r level gen _; do
    out=$("$duel" play "$cand/champions/gen-$(printf %05d "$cgen").blob" "$rank/champions/gen-$(printf %05d "$gen").blob" \
      --games 288 | head -1)
    w=$(sed -E 's/.* wins ([0-9]+), B .*/\1/' <<< "$out")
    l=$(sed -E 's/.*, B .* wins ([0-9]+), draws.*/\1/' <<< "$out")
    [ "${wl[$k]}" = "$w:$l" ] || fail "$cand vs $rank level $level: compare ${wl[$k]}, play $w:$l"
    k=$((k + 1))
    n=$((n + 1))
  done < <(tail -n +2 "$rank/dominance.csv")
done < <(tail -n +2 a.csv)
[ "$n" -gt 6 ] || fail "only $n comparisons checked"

# the same with 3 threads and nothing cached, and with everything cached
"$duel" compare r1 r2 r3 --against r1 r2 r3 --threads 3 --cache fresh.csv --csv b.csv --json b.json > b.txt
cmp a.csv b.csv && cmp a.json b.json || fail "3 threads and no cache give other results"
grep -q "($n played, 0 from the cache)" b.txt || fail "$(head -1 b.txt)"
"$duel" compare r1 r2 r3 --against r1 r2 r3 --csv c.csv --json c.json > c.txt
cmp a.csv c.csv && cmp a.json c.json || fail "the cache gives other results"
grep -q "(0 played, $n from the cache)" c.txt || fail "$(head -1 c.txt)"
# an extended compare plays only what is new
"$duel" run --config "$cfg" --generations 12 --seed 4 --out r4 --quiet
"$duel" compare r1 --against r2 r3 r4 > d.txt
levels4=$(($(wc -l < r4/dominance.csv) - 1))
grep -q "($levels4 played, " d.txt || fail "extended: $(head -1 d.txt)"

# bad input: one line, exit 2
expect_bad "an empty ranking: --against names no run but itself" compare r1 --against r1
expect_bad "an empty ranking: --against names no run" compare r1 --against
expect_bad "which runs" compare --against r1
expect_bad "nope: not a run directory" compare r1 --against nope
mkdir empty
expect_bad "empty/config.ini" compare r1 --against empty
expect_bad "given twice" compare r1 --against r2 r2
cp -r r3 r5
sed -i 's/^generations = .*/generations = 20/' r5/config.ini
expect_bad "r5: not a finished run (12 of 20 generations): resume it first" compare r1 --against r5
cp -r r3 r6
head -n -1 r6/dominance.csv > r6/d && mv r6/d r6/dominance.csv
expect_bad "r6/dominance.csv: .* levels, but the checkpoint has" compare r1 --against r6
rm r3/champions/gen-00000.blob
expect_bad "r3/champions/gen-00000.blob" compare r1 --against r3
printf '# duel_evolve compare cache 1, duel world 1: a_hash,b_hash,wins_a,wins_b,draws,timeouts\n0123,zz\n' > bad.csv
expect_bad "bad.csv:2: not a cache entry" compare r1 --against r2 --cache bad.csv
expect_bad "unknown option '--bogus'" compare r1 --against r2 --bogus
echo "compare: $n comparisons equal to play --games 288"
