#!/usr/bin/env bash
# fixed.sh DUEL_EVOLVE CHECK - evolution against fixed opponents from the outside: 1 thread = 2 threads = killed
# and resumed, its records (the champion against each opponent, the strength series), bad [opponents] input.
set -euo pipefail
duel=$1
what=$2
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=/dev/null
. "$here/cli_lib.sh"

# an opponent of each kind: a builtin, a champion blob, a genome file (from a tiny coevolution)
"$duel" run --config "$here/coev-small.ini" --out "$tmp/co" --generations 2 --quiet --set pop_size=12
cat > "$tmp/fx.ini" <<INI
[run]
generations = 8
seed = 5
strength_every = 3
[neat]
pop_size = 48
[opponents]
play = builtin:forager-hunter, $tmp/co/champions/gen-00001.blob, $tmp/co/champions/gen-00000.genome
games = comparison:3
fitness = wins-losses
INI

# Everything of a run directory but timings and the log.
same_run() {
  diff -r "$1/champions" "$2/champions" || fail "champions differ"
  cmp "$1/checkpoint.bin" "$2/checkpoint.bin" || fail "checkpoint differs"
  cmp "$1/strength.csv" "$2/strength.csv" || fail "strength.csv differs"
  diff <(sed 's/,[^,]*$//' "$1/generations.csv") <(sed 's/,[^,]*$//' "$2/generations.csv") || fail "generations.csv differs"
}

case "$what" in
threads)
  "$duel" run --config "$tmp/fx.ini" --out "$tmp/t1" --threads 1 --quiet
  "$duel" run --config "$tmp/fx.ini" --out "$tmp/t2" --threads 2 --quiet
  same_run "$tmp/t1" "$tmp/t2"
  # the run keeps its opponents: it resumes the same after the files it was given are gone
  "$duel" run --config "$tmp/fx.ini" --out "$tmp/t3" --threads 2 --quiet --generations 4
  rm -rf "$tmp/co"
  "$duel" resume "$tmp/t3" --generations 8 --quiet
  same_run "$tmp/t1" "$tmp/t3"
  [ "$(ls "$tmp/t1/opponents")" = "$(printf '02.blob\n03.blob')" ] || fail "opponents/: $(ls "$tmp/t1/opponents")"
  # a changed copy is another opponent: refused
  printf 'x' >> "$tmp/t3/opponents/02.blob"
  expect_bad "opponents/02.blob" resume "$tmp/t3" --generations 9
  # the header names the opponents, and each row has the champion's results against each
  head -1 "$tmp/t1/generations.csv" | grep -q ',forager-hunter_wins,forager-hunter_losses,forager-hunter_draws,forager-hunter_timeouts,o2_wins,.*,o3_timeouts,seconds$' ||
    fail "header: $(head -1 "$tmp/t1/generations.csv")"
  [ "$(tail -n +2 "$tmp/t1/generations.csv" | wc -l)" -eq 8 ] || fail "not 8 rows"
  # 3 opponents x 3 layouts x 2 sides: 18 games a host
  [ "$(tail -1 "$tmp/t1/generations.csv" | cut -d, -f10)" = 18 ] || fail "host_games"
  ;;
kill)
  "$duel" run --config "$tmp/fx.ini" --out "$tmp/ref" --threads 2 --quiet --generations 30
  "$duel" run --config "$tmp/fx.ini" --out "$tmp/k" --threads 2 --quiet --generations 30 & pid=$!
  sleep 0.$((RANDOM % 4 + 3)); kill -9 "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true
  for i in 1 2 3; do
    "$duel" resume "$tmp/k" --threads 2 --quiet & pid=$!
    sleep 0.$((RANDOM % 4 + 2)); kill -9 "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true
  done
  "$duel" resume "$tmp/k" --threads 2 --quiet
  same_run "$tmp/ref" "$tmp/k"
  ;;
bad)
  expect_bad "no such builtin" run --config "$tmp/fx.ini" --out "$tmp/b" --set opponents.play=builtin:nobody
  expect_bad "cannot open" run --config "$tmp/fx.ini" --out "$tmp/b" --set opponents.play=$tmp/missing.blob
  printf 'not a blob' > "$tmp/junk.blob"
  expect_bad "not a duel controller" run --config "$tmp/fx.ini" --out "$tmp/b" --set opponents.play=$tmp/junk.blob
  expect_bad "comparison:N with N in 1..144" run --config "$tmp/fx.ini" --out "$tmp/b" --set games=comparison:145
  expect_bad "wins or wins-losses" run --config "$tmp/fx.ini" --out "$tmp/b" --set fitness=losses
  expect_bad "an empty name" run --config "$tmp/fx.ini" --out "$tmp/b" --set "opponents.play=builtin:forager,"
  expect_bad "random_fitness is the coevolution's control" run --config "$tmp/fx.ini" --out "$tmp/b" --set random_fitness=1
  "$duel" run --config "$tmp/fx.ini" --out "$tmp/r" --generations 2 --quiet
  # inspect knows its checkpoint by its magic (neat_checkpoint_kind), as a file as well as a directory
  for x in "$tmp/r" "$tmp/r/checkpoint.bin"; do
    "$duel" inspect "$x" | grep -q "^population checkpoint (a run against fixed opponents), format" ||
      fail "inspect $x: $("$duel" inspect "$x" 2>&1 | head -2)"
  done
  expect_bad "a run's \[opponents\] cannot change" resume "$tmp/r" --set fitness=wins
  sed -i 's/^fitness = wins-losses$/fitness = wins/' "$tmp/r/config.ini"
  expect_bad "other games than config.ini" resume "$tmp/r" --generations 3
  ;;
strength)
  # every 3 generations: 0, 3, 6; each the champion's 288 games against every builtin
  "$duel" run --config "$tmp/fx.ini" --out "$tmp/s" --quiet
  [ "$(cut -d, -f1 "$tmp/s/strength.csv" | tr '\n' ' ')" = "generation 0 3 6 " ] || fail "rows: $(cat "$tmp/s/strength.csv")"
  # the row of generation 6 is the champion's comparison with forager-hunter, as play gives it
  play=$("$duel" play "$tmp/s/champions/gen-00006.blob" builtin:forager-hunter --games 288 --json)
  row=$(sed -n '/^6,/p' "$tmp/s/strength.csv")
  want="$(echo "$play" | sed 's/.*"a_wins":\([0-9]*\),"b_wins":\([0-9]*\),"draws":\([0-9]*\),"timeouts":\([0-9]*\).*/\1,\2,\3,\4/')"
  [ "$(echo "$row" | cut -d, -f18-21)" = "$want" ] || fail "strength row $row, play $want"
  # and a coevolution records the same series for its generation champions
  "$duel" run --config "$here/coev-small.ini" --out "$tmp/c" --generations 4 --quiet --set strength_every=2
  [ "$(cut -d, -f1 "$tmp/c/strength.csv" | tr '\n' ' ')" = "generation 0 2 " ] || fail "coevolution rows"
  # an experiment's report gathers the runs' series (3 rows each: generations 0, 2, 4) and draws them
  (cd "$here" && "$duel" experiment tiny-plan.ini --out "$tmp/e" --set strength_every=2 --quiet)
  runs=$(tail -n +2 "$tmp/e/report/runs.csv" | wc -l)
  [ "$(tail -n +2 "$tmp/e/report/strength.csv" | wc -l)" -eq $((3 * runs)) ] || fail "report/strength.csv"
  if python3 -c 'import matplotlib' 2>/dev/null; then
    [ -s "$tmp/e/report/strength.png" ] || fail "no strength figure"
  fi
  # and a report of runs without the series has none
  (cd "$here" && "$duel" experiment tiny-plan.ini --out "$tmp/e2" --set generations=3 --quiet)
  [ ! -e "$tmp/e2/report/strength.csv" ] || fail "a strength.csv without the series"
  ;;
*)
  fail "unknown check $what"
  ;;
esac
echo "ok: fixed $what"
