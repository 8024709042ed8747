#!/usr/bin/env bash
# duel_run.sh - duel_evolve run/resume/config from the outside: thread-count independence, kill -9 and Ctrl-C resumes, configuration errors.
set -euo pipefail
duel=$1
what=$2
cfg=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=/dev/null
. "$(dirname "$0")/cli_lib.sh"

# Everything of a run directory but timings and the log: champions, the
# dominance table, the checkpoint, and generations.csv without its seconds column.
same_run() {
  diff -r "$1/champions" "$2/champions" || { echo "champions differ"; exit 1; }
  cmp "$1/dominance.csv" "$2/dominance.csv" || { echo "dominance.csv differs"; exit 1; }
  cmp "$1/checkpoint.bin" "$2/checkpoint.bin" || { echo "checkpoint differs"; exit 1; }
  diff <(cut -d, -f1-16 "$1/generations.csv") <(cut -d, -f1-16 "$2/generations.csv") ||
    { echo "generations.csv differs"; exit 1; }
  [ "$(ls "$1/champions" | wc -l)" -gt 0 ] || { echo "no champions"; exit 1; }
}

case "$what" in
threads)
  "$duel" run --config "$cfg" --out "$tmp/t1" --threads 1 --quiet
  "$duel" run --config "$cfg" --out "$tmp/t2" --threads 2 --quiet
  same_run "$tmp/t1" "$tmp/t2"
  # and a different seed is a different run
  "$duel" run --config "$cfg" --out "$tmp/t3" --threads 2 --quiet --seed 8 --generations 3
  ! cmp -s "$tmp/t1/champions/gen-00002.blob" "$tmp/t3/champions/gen-00002.blob" ||
    { echo "seed 8 gave seed 7's champion"; exit 1; }
  ;;
kill)
  "$duel" run --config "$cfg" --out "$tmp/ref" --threads 2 --quiet
  # killed at random moments, again and again, then resumed to the end
  "$duel" run --config "$cfg" --out "$tmp/k" --threads 2 --quiet & pid=$!
  sleep 0.$((RANDOM % 5 + 2)); kill -9 "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true
  kills=1
  for i in 1 2 3 4 5; do
    "$duel" resume "$tmp/k" --threads 2 --quiet & pid=$!
    sleep 0.$((RANDOM % 6 + 1)); kill -9 "$pid" 2>/dev/null && kills=$((kills + 1)) || true; wait "$pid" 2>/dev/null || true
  done
  "$duel" resume "$tmp/k" --threads 1 --quiet
  same_run "$tmp/ref" "$tmp/k"
  echo "identical after $kills kill -9"
  ;;
interrupt)
  # 20 generations, and the interrupt once 2 are done (not after a fixed sleep: a faster build finished the
  # whole run of 10 before a 0.5 s sleep ended)
  "$duel" run --config "$cfg" --out "$tmp/ref" --threads 2 --quiet --generations 20
  rc=0
  "$duel" run --config "$cfg" --out "$tmp/i" --threads 2 --quiet --generations 20 2> "$tmp/err" & pid=$!
  for _ in $(seq 2000); do # generations.csv: a header, then a line per population and generation
    [ "$(cat "$tmp/i/generations.csv" 2> /dev/null | wc -l)" -ge 5 ] && break
    kill -0 "$pid" 2> /dev/null || break
    sleep 0.01
  done
  # one process per run directory
  expect_bad "is in use by another duel_evolve" resume "$tmp/i"
  # twice at once, as `timeout` delivers it (to the process and to its group): still the clean stop
  kill -INT "$pid" 2> /dev/null || true; kill -INT "$pid" 2> /dev/null || true; wait "$pid" || rc=$?
  if [ "$rc" -eq 0 ]; then echo "the run finished before Ctrl-C: nothing tested"; exit 1; fi
  [ "$rc" -eq 130 ] || { echo "Ctrl-C: exit $rc, expected 130"; cat "$tmp/err"; exit 1; }
  grep -q "duel_evolve resume $tmp/i" "$tmp/err" || { echo "no resume hint: $(cat "$tmp/err")"; exit 1; }
  grep -q "interrupted" "$tmp/i/log.txt" || { echo "interrupt not logged"; exit 1; }
  "$duel" resume "$tmp/i" --quiet
  same_run "$tmp/ref" "$tmp/i"
  ;;
overrides)
  "$duel" run --config "$cfg" --out "$tmp/o" --quiet --generations 3
  "$duel" resume "$tmp/o" --quiet --generations 5 --set add_node_prob=0.05 --set coevolution.hof_opponents=6
  grep -q "override add_node_prob=0.05" "$tmp/o/log.txt" || { echo "override not logged"; exit 1; }
  # stored with the generation it applies from ([overrides], issue 49: [neat] and [coevolution] keep generation 0's)
  grep -qx "from 3 = add_node_prob=0.05, coevolution.hof_opponents=6" "$tmp/o/config.ini" || { echo "override not stored"; exit 1; }
  grep -q "^generations = 5" "$tmp/o/config.ini" || { echo "generations not stored"; exit 1; }
  [ "$(ls "$tmp/o/champions/"*.blob | wc -l)" -eq 5 ] || { echo "not extended to 5 generations"; exit 1; }
  grep -q "resume: generations 3 -> 5 (extended; config.ini now says 5)" "$tmp/o/log.txt" || fail "extension not logged"
  # fewer generations than the run's total: only with --shorten, and never fewer than it has played
  expect_bad "the run has 5 generations in all (config.ini); 4 would shorten it for good: add --shorten" \
    resume "$tmp/o" --generations 4
  expect_bad "the run has played 5 generations already, more than 4" resume "$tmp/o" --generations 4 --shorten
  expect_bad "--shorten with 6 generations, not fewer than the run's 5" resume "$tmp/o" --generations 6 --shorten
  grep -q "^generations = 5" "$tmp/o/config.ini" || fail "a refused resume changed config.ini"
  expect_bad "pop_size cannot change" resume "$tmp/o" --set pop_size=40
  expect_bad "seed cannot change" resume "$tmp/o" --set seed=9
  expect_bad "unknown key 'add_nod_prob' (did you mean 'add_node_prob'?)" resume "$tmp/o" --set add_nod_prob=1
  ;;
config)
  # --dump loads back unchanged, and the paper's file is the defaults' twin where it speaks
  "$duel" config --dump --config "$cfg" > "$tmp/a.ini"
  "$duel" config --dump --config "$tmp/a.ini" > "$tmp/b.ini"
  cmp "$tmp/a.ini" "$tmp/b.ini" || { echo "dump does not round-trip"; exit 1; }
  grep -q "^pop_size = 32" "$tmp/a.ini" || { echo "dump lost pop_size"; exit 1; }
  printf '[neat]\npop_size = 32\nadd_nod_prob = 0.1\n' > "$tmp/typo.ini"
  expect_bad "typo.ini:3: unknown key 'add_nod_prob' (did you mean 'add_node_prob'?)" \
    run --config "$tmp/typo.ini" --out "$tmp/never"
  printf '[neat]\ngenerations = 5\n' > "$tmp/wrong.ini"
  expect_bad "wrong.ini:2: key 'generations' belongs in section \[run\], not \[neat\]" \
    run --config "$tmp/wrong.ini" --out "$tmp/never"
  printf '[coevolution]\nhof_opponents = lots\n' > "$tmp/value.ini"
  expect_bad "value.ini:2: bad value 'lots' for hof_opponents" run --config "$tmp/value.ini" --out "$tmp/never"
  printf '[robots]\nx = 1\n' > "$tmp/section.ini"
  expect_bad "section.ini:2: unknown section \[robots\]" run --config "$tmp/section.ini" --out "$tmp/never"
  expect_bad "missing.ini: cannot open" run --config "$tmp/missing.ini" --out "$tmp/never"
  printf '[neat]\nn_inputs = 5\n' > "$tmp/io.ini"
  expect_bad "n_inputs must be 12" run --config "$tmp/io.ini" --out "$tmp/never"
  [ ! -e "$tmp/never" ] || { echo "a bad configuration created the run directory"; exit 1; }
  # --out may name a directory whose parents do not exist yet (runs/quick on a fresh checkout)
  "$duel" run --config "$cfg" --out "$tmp/deep/er/run" --quiet --generations 1
  [ -f "$tmp/deep/er/run/checkpoint.bin" ] || { echo "no run in a new nested directory"; exit 1; }
  "$duel" run --config "$cfg" --out "$tmp/once" --quiet --generations 1
  expect_bad "already holds a run" run --config "$cfg" --out "$tmp/once"
  expect_bad "which run directory" resume
  expect_bad "config.ini: cannot open" resume "$tmp/nothing"
  # a corrupt checkpoint is refused with its offset, and nothing is lost
  printf 'garbage' | dd of="$tmp/once/checkpoint.bin" bs=1 seek=100 conv=notrunc 2>/dev/null
  expect_bad "checkpoint.bin: offset [0-9]*: " resume "$tmp/once"
  # a profile among the overrides comes first, wherever it stands: the other overrides refine it
  "$duel" config --dump --config "$cfg" --set add_conn_rule=any --set profile=neat-cpp-1.2.1 > "$tmp/p.ini"
  grep -qx "add_conn_rule = any" "$tmp/p.ini" && grep -qx "species_rep = champion" "$tmp/p.ini" ||
    { echo "config: the profile did not come first"; exit 1; }
  "$duel" run --config "$cfg" --out "$tmp/prof" --quiet --generations 2 --set add_conn_rule=any \
    --set neat.profile=neat-cpp-1.2.1
  grep -qx "add_conn_rule = any" "$tmp/prof/config.ini" && grep -qx "profile = neat-cpp-1.2.1" "$tmp/prof/config.ini" ||
    { echo "run: the profile did not come first"; exit 1; }
  # and such a run resumes (its config.ini reads back to the same configuration)
  "$duel" resume "$tmp/prof" --quiet --generations 3
  # NEAT C++ 1.2.1's own reproduction is neatcpp_duel's (tools/neatcpp): duel_evolve refuses such a run, and
  # refuses to resume one (libneat would go on where the release reproduced)
  expect_bad "only neatcpp_duel, built against a checkout of the release, runs it" \
    run --config "$cfg" --out "$tmp/never" --set run.reproduction=neat-cpp-1.2.1
  [ ! -e "$tmp/never" ] || { echo "a refused reproduction created the run directory"; exit 1; }
  ! grep -q "^reproduction" "$tmp/prof/config.ini" || { echo "reproduction = libneat written"; exit 1; }
  sed -i 's/^\[run\]$/[run]\nreproduction = neat-cpp-1.2.1/' "$tmp/prof/config.ini"
  expect_bad "cannot be resumed (the release's populations are in no file)" resume "$tmp/prof" --generations 4
  "$duel" config --dump --config "$tmp/prof/config.ini" | grep -qx "reproduction = neat-cpp-1.2.1" ||
    { echo "reproduction not dumped"; exit 1; }
  ;;
ladder)
  "$duel" run --config "$cfg" --out "$tmp/l" --quiet --generations 4
  "$duel" ladder "$tmp/l" > "$tmp/ladder.txt"
  levels=$(($(wc -l < "$tmp/l/dominance.csv") - 1))
  [ "$(($(wc -l < "$tmp/l/ladder.csv") - 1))" -eq "$levels" ] || { echo "ladder.csv: not one row per dominant"; exit 1; }
  head -1 "$tmp/l/ladder.csv" | grep -q "^level,generation,population,hidden,connections,idle_wins,idle_losses,.*forager-hunter_losses,total_wins,total_losses,world,step$" ||
    { echo "ladder.csv header: $(head -1 "$tmp/l/ladder.csv")"; exit 1; }
  # each row: wins and losses of 288 games per built-in, the totals their sums
  tail -n +2 "$tmp/l/ladder.csv" | awk -F, '{ w = 0; l = 0
      for (i = 6; i < 16; i += 2) { if ($i + $(i + 1) > 288) exit 1; w += $i; l += $(i + 1) }
      if (w != $16 || l != $17 || NF != 19 || $18 != "v1" || $19 != "sync") exit 1 }' || { echo "ladder.csv rows do not add up"; exit 1; }
  # the ladder's numbers are play's numbers
  gen=$(sed -n 2p "$tmp/l/ladder.csv" | cut -d, -f2)
  "$duel" play "$tmp/l/champions/gen-$(printf %05d "$gen").blob" builtin:forager --games 288 > "$tmp/play.txt"
  want=$(sed -n 2p "$tmp/l/ladder.csv" | cut -d, -f10,11 | tr , :)
  grep -q "wins" "$tmp/play.txt" || { echo "play printed no wins"; exit 1; }
  got=$(grep -o "wins [0-9]*" "$tmp/play.txt" | head -2 | grep -o "[0-9]*" | paste -sd:)
  [ "$got" = "$want" ] || { echo "ladder says $want against forager, play says $got"; cat "$tmp/play.txt"; exit 1; }
  # play --json: the same numbers
  "$duel" play "$tmp/l/champions/gen-$(printf %05d "$gen").blob" builtin:forager --games 288 --json > "$tmp/play.json"
  python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print("%d:%d" % (d["a_wins"], d["b_wins"]))' \
    "$tmp/play.json" | grep -qx "$want" || fail "play --json: $(cat "$tmp/play.json"), expected $want"
  "$duel" play builtin:forager builtin:idle --json | python3 -c 'import json, sys; d = json.load(sys.stdin)
assert d["games"] == 1 and d["food"] == "training" and d["west"] == "builtin:forager", d
assert d["outcome"] in ("west_wins", "east_wins", "draw", "timeout") and len(d["energy"]) == 2, d' ||
    fail "play --json of one game"
  # a part of the ladder: the levels and strategies asked for, as JSON, ladder.csv left whole
  cp "$tmp/l/ladder.csv" "$tmp/whole.csv"
  "$duel" ladder "$tmp/l" --levels 1 --against forager,idle --json > "$tmp/part.json"
  cmp -s "$tmp/whole.csv" "$tmp/l/ladder.csv" || fail "a partial ladder rewrote ladder.csv"
  python3 - "$tmp/part.json" "$tmp/whole.csv" <<'PY' || fail "ladder --json: $(cat "$tmp/part.json")"
import csv, json, sys
d = json.load(open(sys.argv[1]))
row = next(csv.DictReader(open(sys.argv[2])))
assert d["against"] == ["forager", "idle"] and d["games"] == 288 and len(d["levels"]) == 1, d
lv = d["levels"][0]
assert lv["level"] == 1 and lv["generation"] == int(row["generation"]), (lv, row)
for name in ("forager", "idle"):
    r = lv["results"][name]
    assert (r["wins"], r["losses"]) == (int(row[name + "_wins"]), int(row[name + "_losses"])), (name, r, row)
    assert r["wins"] + r["losses"] + r["draws"] + r["timeouts"] == 288, r
assert lv["total_wins"] == sum(lv["results"][n]["wins"] for n in ("forager", "idle"))
PY
  "$duel" ladder "$tmp/l" --levels 1 --against idle --csv "$tmp/part.csv" > /dev/null
  head -1 "$tmp/part.csv" | grep -qx "level,generation,population,hidden,connections,idle_wins,idle_losses,total_wins,total_losses,world,step" ||
    fail "ladder --csv: $(head -1 "$tmp/part.csv")"
  expect_bad "has $levels dominance level" ladder "$tmp/l" --levels "1-$((levels + 1))"
  expect_bad "--against takes built-in strategies" ladder "$tmp/l" --against idle,nobody
  expect_bad "--top and --levels" ladder "$tmp/l" --top --levels 1
  expect_bad "dominance.csv: cannot open" ladder "$tmp/none"
  ;;
*)
  echo "unknown case $what"; exit 2;;
esac
