#!/usr/bin/env bash
# lcm_cli.sh - the duel over LCM from the outside: logs against `play --trace`, bad input, three processes over
# tcpq:// with LCM's Java hub on loopback, a killed controller, lcm-logplayer, run's champion games, Python.
# Hostile input: crafted logs, and a hostile publisher on the bus during a game.
# usage: lcm_cli.sh CHECK DUEL_EVOLVE DUEL_BENCH JAVA LCM_JAR LCM_LOGPLAYER PYTHON3 PYTHON_TYPES_DIR COEV_INI LCM_HOSTILE
set -euo pipefail
what=$1 duel=$2 bench=$3 java=$4 jar=$5 logplayer=$6 python=$7 pytypes=$8 ini=$9 hostile=${10}
tmp=$(mktemp -d)
pids=()
cleanup() {
  local p
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${pids[@]}"; do wait "$p" 2>/dev/null || true; done
  rm -rf "$tmp"
}
trap cleanup EXIT
# shellcheck source=/dev/null
. "$(dirname "$0")/../tools/cli_lib.sh"
skip() { echo "SKIP: $*"; exit 77; }
ms() { echo $(( $(date +%s%N) / 1000000 )); }

# LCM's TCP hub (liblcm-java) on a free loopback port, checked to be this test's hub: sets $hub_port.
# shellcheck source=/dev/null
. "$(dirname "$0")/lcm_hub.sh"
start_hub() {
  [ -x "$java" ] || skip "no java (Debian default-jre-headless; scripts/deps.sh installs it)"
  [ -f "$jar" ] || skip "no $jar (Debian liblcm-java; scripts/deps.sh installs it)"
  lcm_hub_start "$java" "$jar" "$tmp/hub" || fail "LCM's TCP hub did not start: $lcm_hub_error"
  pids+=("$lcm_hub_pid")
  hub_port=$lcm_hub_port
}

blobs() { "$bench" --write-blobs "$tmp" > /dev/null; }

# A step's answer, for the games that check states and not timing: generous, because on a busy machine (the
# sanitized build, two suites at once) a node can stall for seconds (seen: 2 s was not enough once under ASan).
# The checks of a silent controller set their own short timeout.
step_ms=15000

case "$what" in
log)
  # one game, recorded as an LCM log: `log dump` prints `play --trace` byte for byte, `log info` the outcome
  blobs
  for game in "builtin:forager-hunter builtin:forager --food 0" "$tmp/net39a.blob $tmp/net202a.blob --food 140 --side east" \
              "builtin:hunter builtin:forager-hunter" "$tmp/net202b.blob builtin:idle --food 77"; do
    # shellcheck disable=SC2086
    "$duel" play $game --trace "$tmp/t.csv" --lcm-log "$tmp/g.lcm" > "$tmp/play.txt"
    "$duel" log dump "$tmp/g.lcm" > "$tmp/d.csv"
    cmp "$tmp/t.csv" "$tmp/d.csv" || fail "$game: log dump differs from play --trace"
    "$duel" log info "$tmp/g.lcm" > "$tmp/info.txt"
    steps=$(sed -n 's/.* after \([0-9]*\) steps$/\1/p' "$tmp/play.txt")
    [ "$(($(wc -l < "$tmp/t.csv") - 1))" -eq "$steps" ] || fail "$game: trace rows"
    grep -qxF "$(sed -n 2p "$tmp/play.txt")" <(sed -n 's/^outcome: //p' "$tmp/info.txt") || fail "$game: outcome"
    grep -qxF "$(sed -n 3p "$tmp/play.txt")" "$tmp/info.txt" || fail "$game: energies"
    grep -qxF "game: $(sed -n 1p "$tmp/play.txt")" "$tmp/info.txt" || fail "$game: names"
    grep -qx "complete steps: $steps" "$tmp/info.txt" || fail "$game: complete steps"
    for ch in DUEL_SENSE_WEST DUEL_SENSE_EAST DUEL_MOTOR_WEST DUEL_MOTOR_EAST; do
      grep -qx "channel $ch: $steps messages" "$tmp/info.txt" || fail "$game: $ch count"
      [ "$("$duel" log dump "$tmp/g.lcm" --channel $ch | wc -l)" -eq $((steps + 1)) ] || fail "$game: dump $ch"
    done
    grep -qx "channel DUEL_STATE: $((steps + 1)) messages" "$tmp/info.txt" || fail "$game: state count"
    grep -qx "duration: $((steps / 100)).$(printf '%02d' $((steps % 100)))0000 s (first to last event)" "$tmp/info.txt" ||
      fail "$game: nominal duration: $(grep duration "$tmp/info.txt")"
    "$duel" log dump "$tmp/g.lcm" --channel DUEL_STATE > "$tmp/s.csv"
    # the raw state: start positions in Q16.16, west's heading pi as the int32 -2^31
    [ "$(sed -n 2p "$tmp/s.csv" | cut -d, -f1,5-8)" = "0,6553600,19660800,-2147483648,78643200" ] ||
      fail "$game: first state $(sed -n 2p "$tmp/s.csv" | cut -c1-80)"
  done
  # the same game twice: the same bytes (nominal clock)
  "$duel" play builtin:hunter builtin:forager --lcm-log "$tmp/a.lcm" > /dev/null
  "$duel" play builtin:hunter builtin:forager --lcm-log "$tmp/b.lcm" > /dev/null
  cmp "$tmp/a.lcm" "$tmp/b.lcm" || fail "the same game gave different logs"
  ;;
bad-input)
  "$duel" play builtin:forager-hunter builtin:forager --food 9 --lcm-log "$tmp/g.lcm" > /dev/null
  size=$(stat -c %s "$tmp/g.lcm")
  # truncated: the events before the cut are printed, one line names the offset, exit 2
  head -c $((size - 100)) "$tmp/g.lcm" > "$tmp/cut.lcm"
  rc=0; "$duel" log dump "$tmp/cut.lcm" > "$tmp/cut.csv" 2> "$tmp/err.txt" || rc=$?
  [ "$rc" -eq 2 ] || fail "truncated dump: exit $rc"
  [ "$(wc -l < "$tmp/err.txt")" -eq 1 ] && grep -q "cut.lcm: offset [0-9]*: truncated event" "$tmp/err.txt" ||
    fail "truncated dump: $(cat "$tmp/err.txt")"
  "$duel" log dump "$tmp/g.lcm" > "$tmp/full.csv"
  rows=$(($(wc -l < "$tmp/cut.csv") - 1))
  [ "$rows" -gt 100 ] && [ "$rows" -lt $(($(wc -l < "$tmp/full.csv") - 1)) ] || fail "truncated dump: $rows rows"
  cmp <(head -$((rows + 1)) "$tmp/full.csv") "$tmp/cut.csv" || fail "truncated dump: rows before the cut differ"
  expect_bad "cut.lcm: offset [0-9]*: truncated event" log info "$tmp/cut.lcm"
  expect_bad "cut.lcm: offset [0-9]*: truncated event" log dump "$tmp/cut.lcm" --channel DUEL_STATE
  head -c 40 "$tmp/g.lcm" > "$tmp/cut2.lcm"
  expect_bad "cut2.lcm: offset 0: truncated event" log dump "$tmp/cut2.lcm"
  # not LCM at all, empty, missing
  printf 't,west_x\n0,100\n' > "$tmp/trace.lcm"
  expect_bad "trace.lcm: offset 0: not an LCM event log" log info "$tmp/trace.lcm"
  expect_bad "trace.lcm: offset 0: not an LCM event log" log dump "$tmp/trace.lcm"
  : > "$tmp/empty.lcm"
  expect_bad "empty.lcm: empty file, not an LCM event log" log dump "$tmp/empty.lcm"
  expect_bad "missing.lcm: cannot open" log info "$tmp/missing.lcm"
  # a message of format version 99 is refused, not guessed at. The first event is the west net message
  # (28-byte event header, "DUEL_NET", 8-byte fingerprint, then the big-endian version)
  cp "$tmp/g.lcm" "$tmp/v99.lcm"
  printf '\x63' | dd of="$tmp/v99.lcm" bs=1 seek=47 conv=notrunc status=none
  expect_bad "v99.lcm: event 0 at offset 0: DUEL_NET: duel.net_t format version 99, this reader knows only version 1" \
    log dump "$tmp/v99.lcm"
  expect_bad "format version 99" log info "$tmp/v99.lcm"
  expect_bad "format version 99" log dump "$tmp/v99.lcm" --channel DUEL_NET
  # the first state message (its channel name, then fingerprint and version)
  cp "$tmp/g.lcm" "$tmp/v99s.lcm"
  at=$(grep -abo DUEL_STATE "$tmp/g.lcm" | sed -n "1s/:.*//p") # (sed reads it all: head would end grep by SIGPIPE)
  printf '\x63' | dd of="$tmp/v99s.lcm" bs=1 seek=$((at + 10 + 8 + 3)) conv=notrunc status=none
  expect_bad "v99s.lcm: event 2 at offset [0-9]*: DUEL_STATE: duel.state_t format version 99, this reader knows only version 1" \
    log dump "$tmp/v99s.lcm"
  expect_bad "format version 99" log dump "$tmp/v99s.lcm" --channel DUEL_STATE
  # another fingerprint on the channel (another type, or another layout of it)
  cp "$tmp/g.lcm" "$tmp/fp.lcm"
  printf '\x00' | dd of="$tmp/fp.lcm" bs=1 seek=40 conv=notrunc status=none
  expect_bad "fp.lcm: event 0 at offset 0: DUEL_NET: LCM fingerprint 0x[0-9a-f]* is not duel.net_t's" log dump "$tmp/fp.lcm"
  cp "$tmp/g.lcm" "$tmp/fps.lcm"
  printf '\x00' | dd of="$tmp/fps.lcm" bs=1 seek=$((at + 10 + 2)) conv=notrunc status=none
  expect_bad "fps.lcm: event 2 at offset [0-9]*: DUEL_STATE: LCM fingerprint 0x[0-9a-f]* is not duel.state_t's" \
    log dump "$tmp/fps.lcm"
  # channels
  expect_bad "unknown channel 'FOO'" log dump "$tmp/g.lcm" --channel FOO
  "$duel" log dump "$tmp/g.lcm" --channel DUEL_STATE > /dev/null
  rc=0; "$duel" log 2> /dev/null || rc=$?
  [ "$rc" -eq 2 ] || fail "log without a command: exit $rc"
  expect_bad "unknown log command 'frob' (info, dump)" log frob "$tmp/g.lcm"
  expect_bad "unknown option '--chanel'" log dump "$tmp/g.lcm" --chanel DUEL_STATE
  # play: one game only; a log that cannot be written leaves nothing behind
  expect_bad "--lcm-log records one game" play builtin:idle builtin:idle --games 288 --lcm-log "$tmp/x.lcm"
  expect_bad "nodir/x.lcm: cannot write" play builtin:idle builtin:idle --lcm-log "$tmp/nodir/x.lcm"
  ls "$tmp"/*.tmp 2>/dev/null && fail "a temporary file was left"
  # nodes: arguments
  blobs
  expect_bad "--lcm URL is required" node world --food 3
  expect_bad "--food K|training is required" node world --lcm memq://
  expect_bad "bad food configuration '144'" node world --food 144 --lcm memq://
  expect_bad "--timeout-ms takes milliseconds" node world --food 3 --lcm memq:// --timeout-ms 0
  expect_bad "--side west|east is required" node controller "$tmp/net39a.blob" --lcm memq://
  expect_bad "--side takes west or east" node controller "$tmp/net39a.blob" --side north --lcm memq://
  expect_bad "not a builtin strategy" node controller builtin:forager --side west --lcm memq://
  expect_bad "missing.blob: cannot open" node controller "$tmp/missing.blob" --side west --lcm memq://
  expect_bad "cannot start LCM on 'nonsense://x'" node controller "$tmp/net39a.blob" --side west --lcm nonsense://x
  rc=0; "$duel" node 2> /dev/null || rc=$?
  [ "$rc" -eq 2 ] || fail "node without a command: exit $rc"
  expect_bad "unknown node 'frob' (controller, world)" node frob
  # no hub on that port: one line, ours
  expect_bad "cannot start LCM on 'tcpq://127.0.0.1:1'" node world --food 3 --lcm tcpq://127.0.0.1:1
  ;;
processes)
  # a port another hub holds (another suite running at the same time): our hub exits on it, and that is seen as
  # its failing to start there, never taken for our hub (issue 42)
  start_hub
  taken=$hub_port
  lcm_hub_start "$java" "$jar" "$tmp/hub2" "$taken" || fail "no second hub: $lcm_hub_error"
  pids+=("$lcm_hub_pid")
  [ "$lcm_hub_port" != "$taken" ] || fail "a hub was taken to be on port $taken, which another hub holds"
  lcm_hub_listens "$lcm_hub_pid" "$lcm_hub_port" || fail "the second hub does not listen on its port"
  grep -qi "address already in use\|bind" "$tmp/hub2-$taken.log" || fail "the taken port: $(cat "$tmp/hub2-$taken.log")"
  # the same game as three processes (world + two controllers) over tcpq:// through LCM's Java hub, and in
  # one process (play): the same states, bit for bit
  blobs
  # a champion of a short coevolution, for games that end in collisions (the random networks time out)
  "$duel" run --config "$ini" --out "$tmp/run" --generations 1 --threads 2 --quiet
  cp "$tmp/run/champions/gen-00000.blob" "$tmp/champ.blob"
  cp "$tmp/champ.blob" "$tmp/champ2.blob"
  start_hub
  url=tcpq://127.0.0.1:$hub_port
  for game in "net39a net202a 5 training" "champ net39a training 0" "champ champ2 training 50"; do
    set -- $game
    for food in "$3" "$4"; do
      t0=$(ms)
      "$duel" node controller "$tmp/$1.blob" --side west --lcm "$url" > "$tmp/cw.txt" 2>&1 & cw=$!
      "$duel" node controller "$tmp/$2.blob" --side east --lcm "$url" > "$tmp/ce.txt" 2>&1 & ce=$!
      pids+=("$cw" "$ce")
      "$duel" node world --food "$food" --lcm "$url" --lcm-log "$tmp/w.lcm" --timeout-ms $step_ms > "$tmp/world.txt" ||
        fail "world: $(cat "$tmp/world.txt")"
      wait "$cw" || fail "west controller: $(cat "$tmp/cw.txt")"
      wait "$ce" || fail "east controller: $(cat "$tmp/ce.txt")"
      t1=$(ms)
      "$duel" play "$tmp/$1.blob" "$tmp/$2.blob" --food "$food" --trace "$tmp/p.csv" --lcm-log "$tmp/p.lcm" > "$tmp/play.txt"
      # play's last line names the world and each side's step (issue 49), which a world node does not know
      cmp "$tmp/world.txt" <(sed '$d' "$tmp/play.txt") || fail "world and play print different games"
      "$duel" log dump "$tmp/w.lcm" > "$tmp/w.csv"
      cmp "$tmp/p.csv" "$tmp/w.csv" || fail "the three-process game differs from play --trace"
      for ch in DUEL_STATE DUEL_SENSE_WEST DUEL_SENSE_EAST DUEL_MOTOR_WEST DUEL_MOTOR_EAST; do
        cmp <("$duel" log dump "$tmp/p.lcm" --channel $ch) <("$duel" log dump "$tmp/w.lcm" --channel $ch) ||
          fail "$ch differs between the processes and play"
      done
      steps=$(sed -n 's/.* after \([0-9]*\) steps$/\1/p' "$tmp/play.txt")
      grep -q "^west controller $tmp/$1.blob: $steps steps;" "$tmp/cw.txt" || fail "west controller: $(cat "$tmp/cw.txt")"
      echo "food $food: $1 vs $2, $steps steps over tcpq in $((t1 - t0)) ms, states identical to play"
    done
  done
  # a world other than v1: the world node publishes its rules first, the log carries them, every reader takes
  # the states in that world, and the game is play --world's bit for bit
  printf '[world]\nradius = 12.5\nstart_west = 80 120 90\nstart_energy = 900\ntrain_food = 150 150, 300 300\nfood_range = 250\nwall_range = 120\n' > "$tmp/world.ini"
  "$duel" node controller "$tmp/champ.blob" --side west --lcm "$url" > "$tmp/cw.txt" 2>&1 & cw=$!
  "$duel" node controller "$tmp/net39a.blob" --side east --lcm "$url" > "$tmp/ce.txt" 2>&1 & ce=$!
  pids+=("$cw" "$ce")
  "$duel" node world --food 17 --world "$tmp/world.ini" --lcm "$url" --lcm-log "$tmp/w.lcm" --timeout-ms $step_ms \
    > "$tmp/world.txt" || fail "world: $(cat "$tmp/world.txt")"
  wait "$cw" || fail "west controller: $(cat "$tmp/cw.txt")"
  wait "$ce" || fail "east controller: $(cat "$tmp/ce.txt")"
  "$duel" play "$tmp/champ.blob" "$tmp/net39a.blob" --food 17 --world "$tmp/world.ini" --trace "$tmp/p.csv" \
    --lcm-log "$tmp/p.lcm" > "$tmp/play.txt"
  cmp "$tmp/world.txt" <(sed '$d' "$tmp/play.txt") || fail "world and play print different games in the world"
  tail -1 "$tmp/play.txt" | grep -q "^world [a-z0-9]* (identity [0-9a-f]*); network step: A [a-z]*, B [a-z]*$" ||
    fail "play's world line: $(tail -1 "$tmp/play.txt")"
  "$duel" log dump "$tmp/w.lcm" > "$tmp/w.csv"
  cmp "$tmp/p.csv" "$tmp/w.csv" || fail "the three-process game in the world differs from play --trace"
  "$duel" log info "$tmp/w.lcm" | grep -q "^world: custom [0-9a-f]\{16\}" || fail "log info does not name the world"
  "$duel" log info "$tmp/w.lcm" | grep -q "^channel DUEL_WORLD: 1 messages$" || fail "no world message"
  "$duel" play "$tmp/champ.blob" "$tmp/net39a.blob" --food 17 --trace "$tmp/v1.csv" > /dev/null
  ! cmp -s "$tmp/v1.csv" "$tmp/w.csv" || fail "the world's game is v1's"
  echo "food 17 in another world: identical to play --world, the log names it"
  ;;
kill)
  # kill -9 the east controller in the middle of a game: the world ends it within its timeout, east losing
  blobs
  start_hub
  url=tcpq://127.0.0.1:$hub_port
  timeout_ms=400
  "$duel" node controller "$tmp/net39a.blob" --side west --lcm "$url" > "$tmp/cw.txt" 2>&1 & cw=$!
  "$duel" node controller "$tmp/net202a.blob" --side east --lcm "$url" > "$tmp/ce.txt" 2>&1 & ce=$!
  pids+=("$cw" "$ce")
  "$duel" node world --food 5 --lcm "$url" --period-ms 10 --timeout-ms $timeout_ms --lcm-log "$tmp/k.lcm" \
    > "$tmp/world.txt" 2> "$tmp/world.err" & world=$!
  pids+=("$world")
  # wait until the game runs (the log grows), then kill
  for i in $(seq 100); do [ -s "$tmp/k.lcm.tmp" ] && break; sleep 0.05; done
  sleep 0.5
  kill -9 "$ce"
  t0=$(ms)
  rc=0; wait "$world" || rc=$?
  t1=$(ms)
  elapsed=$((t1 - t0))
  [ "$rc" -eq 1 ] || fail "world: exit $rc, expected 1 ($(cat "$tmp/world.err"))"
  [ "$(wc -l < "$tmp/world.err")" -eq 1 ] || fail "world: $(cat "$tmp/world.err")"
  grep -q "node world: the east controller did not answer step [0-9]* within $timeout_ms ms: east loses, west wins" \
    "$tmp/world.err" || fail "world: $(cat "$tmp/world.err")"
  # at most one step period plus the timeout (and scheduling slack) after the kill
  [ "$elapsed" -le $((timeout_ms + 10 + 300)) ] || fail "the world took $elapsed ms after the kill"
  wait "$cw" || fail "west controller: $(cat "$tmp/cw.txt")"
  grep -q "west wins (the east controller did not answer in time)" "$tmp/cw.txt" || fail "west: $(cat "$tmp/cw.txt")"
  # the game up to the forfeit is a valid log
  "$duel" log info "$tmp/k.lcm" > "$tmp/info.txt" || fail "log info: $(cat "$tmp/info.txt")"
  grep -q "^outcome: west wins (the east controller did not answer in time) after [0-9]* steps" "$tmp/info.txt" ||
    fail "$(cat "$tmp/info.txt")"
  step=$(sed -n 's/.*answer step \([0-9]*\) within.*/\1/p' "$tmp/world.err")
  [ "$("$duel" log dump "$tmp/k.lcm" | wc -l)" -eq $((step + 1)) ] || fail "dump of the forfeited game"
  echo "killed the east controller at step $step: the world exited (status 1) $elapsed ms later (timeout $timeout_ms ms)"
  ;;
logplayer)
  # lcm-logplayer replays a recorded game; LCM's file:// provider records what it publishes, through LCM:
  # the same game comes out
  [ -x "$logplayer" ] || skip "no lcm-logplayer (Debian liblcm-bin; scripts/deps.sh installs it)"
  "$duel" play builtin:forager-hunter builtin:hunter --food 66 --trace "$tmp/t.csv" --lcm-log "$tmp/g.lcm" > /dev/null
  "$logplayer" -s 1000 -l "file://$tmp/replayed.lcm?mode=w" "$tmp/g.lcm" > "$tmp/lp.txt" 2>&1 ||
    fail "lcm-logplayer: $(cat "$tmp/lp.txt")"
  "$duel" log dump "$tmp/replayed.lcm" > "$tmp/r.csv"
  cmp "$tmp/t.csv" "$tmp/r.csv" || fail "the replayed log differs"
  cmp <("$duel" log dump "$tmp/g.lcm" --channel DUEL_STATE) <("$duel" log dump "$tmp/replayed.lcm" --channel DUEL_STATE) ||
    fail "replayed states differ"
  ;;
champion-games)
  # run --record-champion-games: the champion's training-food game from both sides per generation, and the
  # run itself unchanged
  "$duel" run --config "$ini" --out "$tmp/a" --generations 2 --threads 2 --quiet --record-champion-games
  "$duel" run --config "$ini" --out "$tmp/b" --generations 2 --threads 2 --quiet
  cmp "$tmp/a/checkpoint.bin" "$tmp/b/checkpoint.bin" || fail "recording changed the run"
  for g in 00000 00001; do
    cmp "$tmp/a/champions/gen-$g.blob" "$tmp/b/champions/gen-$g.blob" || fail "champion $g"
    for side in west east; do
      f="$tmp/a/games/gen-$g-$side.lcm"
      "$duel" log info "$f" > "$tmp/info.txt" || fail "$f: $(cat "$tmp/info.txt")"
      if [ $side = west ]; then
        grep -q "^game: training food, west champions/gen-$g.blob, east gen-$g best of [AB]$" "$tmp/info.txt" || fail "$f"
      else
        grep -q "^game: training food, west gen-$g best of [AB], east champions/gen-$g.blob$" "$tmp/info.txt" || fail "$f"
      fi
      grep -q "^outcome: " "$tmp/info.txt" && ! grep -q "^outcome: none" "$tmp/info.txt" || fail "$f: no outcome"
      "$duel" log dump "$f" > /dev/null || fail "$f: dump"
    done
  done
  [ ! -e "$tmp/b/games" ] || fail "games/ without the option"
  ;;
python)
  # a recorded log decoded with the PyPI lcm package and the lcm-gen -p types (the README's example)
  # (the package where scripts/deps.sh puts it, NEAT_PY_LCM, off everyone's PATH)
  [ -x "$python" ] || skip "no python3"
  pylcm=${NEAT_PY_LCM:-}
  PYTHONPATH="$pylcm" "$python" -c 'import lcm' 2>/dev/null ||
    skip "no Python lcm package in '$pylcm' (scripts/deps.sh installs it there)"
  for game in "builtin:forager-hunter builtin:idle" "builtin:forager builtin:forager --food 12" \
              "builtin:spinner builtin:hunter --food 100 --side east"; do
    # shellcheck disable=SC2086
    "$duel" play $game --lcm-log "$tmp/g.lcm" > "$tmp/play.txt"
    PYTHONPATH="$pytypes${pylcm:+:$pylcm}" "$python" "$(dirname "$0")/decode_log.py" "$tmp/g.lcm" "$tmp/play.txt" ||
      fail "$game: decode_log.py"
  done
  ;;
hostile-logs)
  # one-event logs whose message lies about a string's length or its size (a negative length crashed
  # log info, log dump and render; a 2 GB one was allocated): exit 2, one line naming the event and offset
  n=0
  while read -r name channel bytes; do
    "$hostile" log "$name" "$tmp/$name.lcm"
    for cmd in "log info" "log dump" "log dump --channel $channel" "render"; do
      set -- $cmd
      if [ "$1" = render ]; then
        expect_bad "$name.lcm: event 0 at offset 0: $channel: " render "$tmp/$name.lcm" --out "$tmp/frames-$name"
        [ ! -e "$tmp/frames-$name" ] || fail "render of $name.lcm created its output"
      elif [ "$#" -eq 2 ]; then
        expect_bad "$name.lcm: event 0 at offset 0: $channel: " "$1" "$2" "$tmp/$name.lcm"
      else
        expect_bad "$name.lcm: event 0 at offset 0: $channel: " "$1" "$2" "$tmp/$name.lcm" "$3" "$4"
      fi
    done
    echo "$name ($((28 + ${#channel} + bytes))-byte log): $("$duel" log info "$tmp/$name.lcm" 2>&1)"
    n=$((n + 1))
  done < <("$hostile" list)
  [ "$n" -ge 10 ] || fail "only $n crafted messages"
  [ "$(stat -c %s "$tmp/motor-negative.lcm")" -eq 94 ] || fail "motor-negative.lcm is not the 94-byte log"
  [ "$(stat -c %s "$tmp/state-negative.lcm")" -eq 62 ] || fail "state-negative.lcm is not the 62-byte log"
  ;;
hostile-bus)
  # a game over tcpq:// while a hostile peer publishes every crafted message on every duel channel every
  # 5 ms: both kinds of node ignore them (and say how many), and the game is play's, bit for bit
  blobs
  start_hub
  url=tcpq://127.0.0.1:$hub_port
  "$hostile" publish "$url" 8 > "$tmp/hostile.txt" & hp=$!
  pids+=("$hp")
  sleep 0.3
  "$duel" node controller "$tmp/net39a.blob" --side west --lcm "$url" > "$tmp/cw.txt" 2>&1 & cw=$!
  "$duel" node controller "$tmp/net202a.blob" --side east --lcm "$url" > "$tmp/ce.txt" 2>&1 & ce=$!
  pids+=("$cw" "$ce")
  "$duel" node world --food 5 --lcm "$url" --lcm-log "$tmp/w.lcm" --timeout-ms $step_ms --period-ms 2 \
    > "$tmp/world.txt" 2> "$tmp/world.err" || fail "world: $(cat "$tmp/world.txt" "$tmp/world.err")"
  wait "$cw" || fail "west controller: $(cat "$tmp/cw.txt")"
  wait "$ce" || fail "east controller: $(cat "$tmp/ce.txt")"
  wait "$hp" || fail "hostile publisher: $(cat "$tmp/hostile.txt")"
  "$duel" play "$tmp/net39a.blob" "$tmp/net202a.blob" --food 5 --trace "$tmp/p.csv" > "$tmp/play.txt"
  cmp "$tmp/world.txt" <(sed '$d' "$tmp/play.txt") || fail "the game under attack differs from play"
  "$duel" log dump "$tmp/w.lcm" > "$tmp/w.csv"
  cmp "$tmp/p.csv" "$tmp/w.csv" || fail "the recorded game under attack differs from play --trace"
  grep -Eq "node world: ignored [0-9]* malformed messages; the first: DUEL_(MOTOR_|NET)" "$tmp/world.err" ||
    fail "world: $(cat "$tmp/world.err")"
  grep -q "node controller west: ignored [0-9]* malformed messages; the first: DUEL_" "$tmp/cw.txt" ||
    fail "west: $(cat "$tmp/cw.txt")"
  grep -q "node controller east: ignored [0-9]* malformed messages; the first: DUEL_" "$tmp/ce.txt" ||
    fail "east: $(cat "$tmp/ce.txt")"
  cat "$tmp/hostile.txt" "$tmp/world.err"; grep ignored "$tmp/cw.txt" "$tmp/ce.txt"
  ;;
*)
  echo "unknown check $what"; exit 2 ;;
esac
echo "ok: $what"
