#!/usr/bin/env bash
# world.sh DUEL_EVOLVE CHECK CONFIG - the world's rules as data from the outside: [world] round trips through
# config.ini and the checkpoint, bad rules refused naming the key, a changed world refused on resume, comparisons
# cached per world, and a variant world's games replayed by an independent model of the rules.
set -euo pipefail
duel=$1
what=$2
cfg=$3
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=/dev/null
. "$here/cli_lib.sh"

# a world unlike v1 in every chosen rule
cp "$here/fixtures/world-variant.ini" "$tmp/variant.ini"

case "$what" in
config)
  # config --dump writes every rule; reading the dump back gives the same dump
  "$duel" config --dump --config "$tmp/variant.ini" > "$tmp/d1.ini"
  grep -q '^food_range = 250$' "$tmp/d1.ini" || fail "the dump lacks the override"
  grep -q '^candidates = 60 75, 60 225' "$tmp/d1.ini" || fail "the dump lacks v1's candidates"
  "$duel" config --dump --config "$tmp/d1.ini" > "$tmp/d2.ini"
  cmp "$tmp/d1.ini" "$tmp/d2.ini" || fail "[world] does not round-trip through the dump"
  # a run writes the rules into config.ini and its checkpoint: ladder and play read them from there
  cat "$cfg" "$tmp/variant.ini" > "$tmp/run.ini"
  "$duel" run --config "$tmp/run.ini" --out "$tmp/r" --generations 2 --quiet
  id=$(sed -n 's/^; a world of its own (identity \([0-9a-f]*\)).*/\1/p' "$tmp/r/config.ini")
  [ -n "$id" ] || fail "config.ini does not name the world's identity"
  "$duel" ladder "$tmp/r" --against forager --json > "$tmp/l.json"
  grep -q "\"world_id\":\"$id\"" "$tmp/l.json" || fail "ladder did not play in the run's world: $(cat "$tmp/l.json")"
  # the checkpoint is the run's record: ladder takes its world even when config.ini is gone
  mv "$tmp/r/config.ini" "$tmp/config.ini.away"
  "$duel" ladder "$tmp/r" --against forager --json > "$tmp/l2.json"
  grep -q "\"world_id\":\"$id\"" "$tmp/l2.json" || fail "ladder did not read the world from the checkpoint"
  mv "$tmp/config.ini.away" "$tmp/r/config.ini"
  # the same games as --world with the rules file
  "$duel" play "$tmp/r/champions/gen-00001.blob" builtin:forager --games 288 > "$tmp/p1"
  "$duel" play "$tmp/r/champions/gen-00001.blob" builtin:forager --games 288 --world "$tmp/variant.ini" > "$tmp/p2"
  "$duel" play "$tmp/r/champions/gen-00001.blob" builtin:forager --games 288 --world v1 > "$tmp/p3"
  cmp "$tmp/p1" "$tmp/p2" || fail "play did not take the run's world"
  ! cmp -s "$tmp/p1" "$tmp/p3" || fail "v1 and the variant gave the same 288 games"
  ;;
resume)
  cat "$cfg" "$tmp/variant.ini" > "$tmp/run.ini"
  "$duel" run --config "$tmp/run.ini" --out "$tmp/r" --generations 2 --quiet
  expect_bad "a run's \[world\] rules cannot change" resume "$tmp/r" --set world.food_range=300
  cp "$tmp/r/config.ini" "$tmp/keep.ini"
  sed -i 's/^food_range = 250$/food_range = 251/' "$tmp/r/config.ini"
  expect_bad "was made in world custom" resume "$tmp/r" --generations 3
  cp "$tmp/keep.ini" "$tmp/r/config.ini"
  sed -i 's/^train_layouts = training$/train_layouts = comparison/' "$tmp/r/config.ini"
  expect_bad "other games than config.ini" resume "$tmp/r" --generations 3
  cp "$tmp/keep.ini" "$tmp/r/config.ini"
  "$duel" resume "$tmp/r" --generations 3 --quiet
  # 1 thread = 2 threads = resumed, in the variant world with the training food drawn per generation
  "$duel" run --config "$tmp/run.ini" --out "$tmp/a" --generations 4 --threads 1 --quiet --set train_layouts=comparison
  "$duel" run --config "$tmp/run.ini" --out "$tmp/b" --generations 2 --threads 2 --quiet --set train_layouts=comparison
  "$duel" resume "$tmp/b" --generations 4 --threads 2 --quiet
  cmp "$tmp/a/checkpoint.bin" "$tmp/b/checkpoint.bin" || fail "resumed != uninterrupted"
  diff -r "$tmp/a/champions" "$tmp/b/champions" || fail "champions differ"
  ;;
bad)
  for bad in "train_food = 700 300:train_food: an item off the board" \
             "start_west = 5 300 180:start_west: the robot would start inside a wall" \
             "start_east = 105 300 0:start_east: the robots would start within the collision distance" \
             "food_range = 0:food_range = '0': expected a whole number" \
             "wall_range = 12.5:wall_range = '12.5': expected a whole number" \
             "train_food = 1 1, 2 2, 3 3, 4 4, 5 5, 6 6, 7 7, 8 8, 9 9, 10 10:train_food: more than 9 positions" \
             "candidates = 60 75:candidates: 1 positions, expected exactly 12" \
             "eat_dist = 0:eat_dist: must be 1 to 150" \
             "rules = v9:rules = 'v9': unknown world" \
             "food_rnge = 3:did you mean 'food_range'"; do
    line=${bad%%:*} want=${bad#*:}
    printf '[world]\n%s\n' "$line" > "$tmp/bad.ini"
    expect_bad "$want" config --dump --config "$tmp/bad.ini"
    expect_bad "$want" play builtin:forager builtin:idle --world "$tmp/bad.ini"
  done
  expect_bad "no such world" play builtin:forager builtin:idle --world v9
  expect_bad "has no \[world\] section" play builtin:forager builtin:idle --world "$cfg"
  ;;
cache)
  # two small runs, compared: the cache holds v1's identity in its world column
  "$duel" run --config "$cfg" --out "$tmp/a" --generations 3 --quiet
  "$duel" run --config "$cfg" --out "$tmp/b" --generations 3 --quiet --seed 9
  "$duel" compare "$tmp/a" --against "$tmp/b" --cache "$tmp/c.csv" > "$tmp/o1"
  v1=$(printf '[world]\nrules = v1\n' > "$tmp/v1.ini"; "$duel" config --dump --config "$tmp/v1.ini" |
       sed -n 's/^; world v1 (identity \([0-9a-f]*\)).*/\1/p')
  head -1 "$tmp/c.csv" | grep -q 'compare cache 2: world,' || fail "not format 2: $(head -1 "$tmp/c.csv")"
  [ "$(tail -n +2 "$tmp/c.csv" | cut -d, -f1 | sort -u)" = "$v1" ] || fail "entries not keyed by world v1 ($v1)"
  n=$(tail -n +2 "$tmp/c.csv" | wc -l)
  # the same entries under another world's identity, with other results: never taken for v1's
  { head -1 "$tmp/c.csv"; tail -n +2 "$tmp/c.csv" | sed 's/^[0-9a-f]*,/0123456789abcdef,/; s/,[0-9]*,[0-9]*,[0-9]*,[0-9]*$/,288,0,0,0/'; } > "$tmp/other.csv"
  "$duel" compare "$tmp/a" --against "$tmp/b" --cache "$tmp/other.csv" > "$tmp/o2"
  grep -q "($n played, 0 from the cache)" "$tmp/o2" || fail "another world's entries were used: $(cat "$tmp/o2")"
  diff <(grep -v 'from the cache' "$tmp/o1") <(grep -v 'from the cache' "$tmp/o2") || fail "results differ"
  [ "$(tail -n +2 "$tmp/other.csv" | wc -l)" -eq $((2 * n)) ] || fail "the other world's entries were not kept"
  # a format-1 cache (before the rules were data) is world v1's: taken, and written back in format 2
  { echo "# duel_evolve compare cache 1, duel world 1: a_hash,b_hash,wins_a,wins_b,draws,timeouts"
    tail -n +2 "$tmp/c.csv" | cut -d, -f2-; } > "$tmp/old.csv"
  "$duel" compare "$tmp/a" --against "$tmp/b" --cache "$tmp/old.csv" > "$tmp/o3"
  grep -q "(0 played, $n from the cache)" "$tmp/o3" || fail "the format-1 cache was not taken: $(cat "$tmp/o3")"
  cmp "$tmp/old.csv" "$tmp/c.csv" || fail "the format-1 cache was not written back as format 2"
  # runs of different worlds are not compared
  cat "$cfg" "$tmp/variant.ini" > "$tmp/run.ini"
  "$duel" run --config "$tmp/run.ini" --out "$tmp/v" --generations 3 --quiet
  expect_bad "runs of different worlds are not compared" compare "$tmp/a" --against "$tmp/v"
  ;;
replay)
  # a variant world's games, traced, and replayed step by step by tests/duelsim/replay_model.py, a model of
  # docs/duel-world.md in double precision that shares no code with the simulator
  "$duel" config --dump --config "$tmp/variant.ini" > "$tmp/full.ini"
  cat "$cfg" "$tmp/variant.ini" > "$tmp/run.ini"
  "$duel" run --config "$tmp/run.ini" --out "$tmp/r" --generations 3 --quiet
  for game in "builtin:forager-hunter builtin:forager training" "builtin:hunter builtin:forager-hunter 17" \
              "$tmp/r/champions/gen-00002.blob builtin:forager-hunter 100" \
              "builtin:forager $tmp/r/champions/gen-00001.blob 143"; do
    set -- $game
    "$duel" play "$1" "$2" --world "$tmp/variant.ini" --food "$3" --trace "$tmp/t.csv" > /dev/null
    food=$3; [ "$food" = training ] && food=-1
    python3 "$here/../duelsim/replay_model.py" "$tmp/full.ini" "$food" "$tmp/t.csv" || fail "replay of $game"
  done
  # and the model can tell: the same trace under v1's rules does not agree
  "$duel" config --dump > "$tmp/v1.ini"
  ! python3 "$here/../duelsim/replay_model.py" "$tmp/v1.ini" 143 "$tmp/t.csv" > /dev/null 2>&1 ||
    fail "the model agreed with a trace of another world"
  ;;
*)
  fail "unknown check $what"
  ;;
esac
echo "ok: world $what"
