#!/usr/bin/env bash
# safety.sh DUEL_EVOLVE CONFIG PLAN CHECK - no command destroys a file it does not own, every record is rebuilt or
# refused with advice that works, every read is bounded (issue 40; docs/hardening.md, "Files that are not ours").
# CONFIG is a small run (tests/tools/coev-small.ini), PLAN a small experiment (tests/tools/tiny-plan.ini).
set -euo pipefail
duel=$1 cfg=$2 plan=$3 what=$4
tmp=$(mktemp -d)
pids=()
trap 'for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null || true; done; rm -rf "$tmp"' EXIT
# shellcheck source=/dev/null
. "$(dirname "$0")/cli_lib.sh"
snapshot() { (cd "$1" && find . -type f ! -name .lock -print0 | sort -z | xargs -0 md5sum); }

case "$what" in
rundir)
  # class 2: run --out an existing directory that is not a run touches nothing there
  mkdir "$tmp/mine"
  printf 'my notes\n' > "$tmp/mine/notes.txt"
  printf 'keep me\n' > "$tmp/mine/generations.csv"
  printf 'keep me too\n' > "$tmp/mine/dominance.csv"
  before=$(snapshot "$tmp/mine"; ls -A "$tmp/mine")
  expect_bad "mine is not empty and not a run directory (it holds 'notes.txt', which is not a run's): choose another --out" \
    run --config "$cfg" --out "$tmp/mine" --generations 1
  [ "$(snapshot "$tmp/mine"; ls -A "$tmp/mine")" = "$before" ] || fail "run --out touched a directory that is not a run"
  # an experiment directory is not a run
  "$duel" experiment "$plan" --out "$tmp/exp" --set generations=1 --quiet > /dev/null
  before=$(snapshot "$tmp/exp")
  expect_bad "exp is not empty and not a run directory (it holds '.*', which is not a run's)" \
    run --config "$cfg" --out "$tmp/exp" --generations 1
  [ "$(snapshot "$tmp/exp")" = "$before" ] || fail "run --out changed an experiment directory"
  # a config.ini that no run wrote
  mkdir "$tmp/cfg"
  printf '[neat]\npop_size = 8\n' > "$tmp/cfg/config.ini"
  expect_bad "cfg is not empty and not a run directory (it holds a config.ini that a run did not write)" \
    run --config "$cfg" --out "$tmp/cfg" --generations 1
  grep -q "pop_size = 8" "$tmp/cfg/config.ini" || fail "config.ini replaced"
  # what still works: an empty directory, and the remains of a run that died before its first checkpoint
  mkdir "$tmp/empty"
  "$duel" run --config "$cfg" --out "$tmp/empty" --generations 1 --quiet
  "$duel" run --config "$cfg" --out "$tmp/died" --generations 1 --quiet
  rm "$tmp/died/checkpoint.bin" "$tmp/died/champions/"*
  "$duel" run --config "$cfg" --out "$tmp/died" --generations 1 --quiet || fail "a run that died before its checkpoint"
  ;;
lock)
  # class 7: deleting .lock while a run works does not let a second writer in; a .lock that is a link is not followed
  "$duel" run --config "$cfg" --out "$tmp/r" --generations 1 --quiet
  "$duel" resume "$tmp/r" --generations 100000 --quiet > /dev/null 2>&1 &
  pids+=($!)
  for _ in $(seq 100); do grep -q "resume at" "$tmp/r/log.txt" 2>/dev/null && break; sleep 0.1; done
  rm "$tmp/r/.lock"
  expect_bad "r is in use by another duel_evolve run or resume" resume "$tmp/r" --generations 100000
  kill -9 "${pids[0]}"
  wait "${pids[0]}" 2>/dev/null || true
  rm -f "$tmp/r/.lock"
  ln -s "$tmp/planted" "$tmp/r/.lock"
  expect_bad "r/.lock is a symbolic link: refusing to follow it (remove it)" resume "$tmp/r" --generations 3
  [ ! -e "$tmp/planted" ] || fail "the .lock link's target was created"
  mkdir "$tmp/e"
  ln -s "$tmp/planted" "$tmp/e/.lock"
  expect_bad "experiment: .*e: .lock is a symbolic link" experiment "$plan" --out "$tmp/e"
  [ ! -e "$tmp/planted" ] || fail "the experiment's .lock link's target was created"
  ;;
bounds)
  # class 4: every reader of a run directory has a cap and reads regular files only (no FIFO wait, no endless file)
  "$duel" run --config "$cfg" --out "$tmp/r" --generations 2 --quiet
  cp -r "$tmp/r" "$tmp/keep"
  for f in generations.csv dominance.csv; do
    rm "$tmp/r/$f"
    mkfifo "$tmp/r/$f"
    timeout 20 "$duel" resume "$tmp/r" --generations 3 --quiet 2> "$tmp/err" && fail "resume read a FIFO $f" || true
    grep -q "$f.*not a regular file" "$tmp/err" || fail "FIFO $f: $(cat "$tmp/err")"
    rm "$tmp/r/$f"
    ln -s /dev/zero "$tmp/r/$f"
    timeout 20 "$duel" resume "$tmp/r" --generations 3 --quiet 2> "$tmp/err" && fail "resume read /dev/zero as $f" || true
    grep -q "$f.*not a regular file" "$tmp/err" || fail "/dev/zero as $f: $(cat "$tmp/err")"
    rm "$tmp/r/$f"
    cp "$tmp/keep/$f" "$tmp/r/$f"
  done
  truncate -s 300M "$tmp/r/generations.csv" # sparse: costs no disk
  timeout 20 "$duel" resume "$tmp/r" --generations 3 --quiet 2> "$tmp/err" && fail "resume read a 300 MB file" || true
  grep -q "generations.csv.*too large" "$tmp/err" || fail "300 MB generations.csv: $(cat "$tmp/err")"
  cp "$tmp/keep/generations.csv" "$tmp/r/generations.csv"
  truncate -s 300M "$tmp/r/dominance.csv" # the run's own record, damaged: rebuilt from the checkpoint
  timeout 20 "$duel" resume "$tmp/r" --quiet || fail "resume did not rebuild a 300 MB dominance.csv"
  cmp "$tmp/keep/dominance.csv" "$tmp/r/dominance.csv" || fail "a 300 MB dominance.csv not rebuilt"
  rm "$tmp/r/dominance.csv"
  mkfifo "$tmp/r/dominance.csv"
  timeout 20 "$duel" ladder "$tmp/r" --top 2> "$tmp/err" && fail "ladder read a FIFO" || true
  grep -q "dominance.csv.*not a regular file" "$tmp/err" || fail "ladder FIFO: $(cat "$tmp/err")"
  mkfifo "$tmp/fifo"
  timeout 20 "$duel" inspect "$tmp/fifo" 2> "$tmp/err" && fail "inspect read a FIFO" || true
  [ -s "$tmp/err" ] || fail "inspect of a FIFO said nothing"
  expect_bad "fifo: cannot open: not a regular file" log info "$tmp/fifo"
  ;;
records)
  # class 3: what the checkpoint holds is rebuilt by resume, byte for byte; what it does not is refused with advice
  # that works; no reader drops a cut last row silently
  "$duel" run --config "$cfg" --out "$tmp/ref" --generations 4 --quiet
  [ "$(wc -l < "$tmp/ref/dominance.csv")" -ge 3 ] || fail "too few levels to test: $(cat "$tmp/ref/dominance.csv")"
  cp -r "$tmp/ref" "$tmp/r"
  head -c -1 "$tmp/ref/dominance.csv" > "$tmp/r/dominance.csv" # the last row lost its newline
  expect_bad "dominance.csv:[0-9]*: the last row is cut short (no newline): resuming the run rebuilds the file" \
    ladder "$tmp/r" --top
  expect_bad "dominance.csv:[0-9]*: the last row is cut short" compare "$tmp/r" --against "$tmp/ref"
  "$duel" resume "$tmp/r" --quiet # a finished run: resume only repairs
  cmp "$tmp/ref/dominance.csv" "$tmp/r/dominance.csv" || fail "a cut dominance.csv not rebuilt"
  grep -q "resume: dominance.csv rebuilt from the checkpoint" "$tmp/r/log.txt" || fail "the rebuild not logged"
  rm "$tmp/r/dominance.csv"
  "$duel" resume "$tmp/r" --quiet
  cmp "$tmp/ref/dominance.csv" "$tmp/r/dominance.csv" || fail "a deleted dominance.csv not rebuilt"
  sed -i 2d "$tmp/r/dominance.csv"
  "$duel" ladder "$tmp/r" --top > /dev/null 2>&1 && fail "ladder took a dominance.csv without level 1" || true
  "$duel" resume "$tmp/r" --generations 5 --quiet
  "$duel" resume "$tmp/ref" --generations 5 --quiet
  cmp "$tmp/ref/dominance.csv" "$tmp/r/dominance.csv" || fail "a row dropped from dominance.csv not rebuilt"
  cmp "$tmp/ref/checkpoint.bin" "$tmp/r/checkpoint.bin" || fail "the repaired run went on differently"
  # strength.csv rows are measured again from champions/gen-G.blob (the same bytes); a row whose champion is gone too
  # is refused with what works
  "$duel" run --config "$cfg" --out "$tmp/s" --generations 5 --set strength_every=2 --quiet
  cp -r "$tmp/s" "$tmp/s2"
  rm "$tmp/s2/strength.csv"
  "$duel" resume "$tmp/s2" --quiet
  cmp "$tmp/s/strength.csv" "$tmp/s2/strength.csv" || fail "a deleted strength.csv not rebuilt"
  grep -q "resume: strength.csv rebuilt (3 rows measured again from champions/)" "$tmp/s2/log.txt" ||
    fail "the strength rebuild not logged"
  head -c -1 "$tmp/s/strength.csv" > "$tmp/s2/strength.csv" # generation 4's row cut
  sed -i 2d "$tmp/s2/strength.csv"                           # generation 0's row lost
  "$duel" resume "$tmp/s2" --quiet
  cmp "$tmp/s/strength.csv" "$tmp/s2/strength.csv" || fail "a cut strength.csv not rebuilt"
  sed -i 3d "$tmp/s2/strength.csv" # generation 2's row, and its champion
  rm "$tmp/s2/champions/gen-00002.blob"
  cp "$tmp/s2/strength.csv" "$tmp/cut.csv"
  expect_bad "s2/strength.csv: generation 2's row is lost and cannot be measured again without champions/gen-00002.blob (No such file or directory): restore either, or resume with --set strength_every=0 to measure nothing more" \
    resume "$tmp/s2"
  cmp "$tmp/cut.csv" "$tmp/s2/strength.csv" || fail "a refused resume changed strength.csv"
  "$duel" resume "$tmp/s2" --set strength_every=0 --generations 6 --quiet # the advice works
  cmp "$tmp/cut.csv" "$tmp/s2/strength.csv" || fail "strength_every=0 measured"
  # generations.csv rows are measured as they happen: lost ones are refused, with advice that works
  cp -r "$tmp/ref" "$tmp/g"
  sed -i 4d "$tmp/g/generations.csv"
  expect_bad "generations.csv:4: generation 1 B follows generation 0 B: rows are missing: rows lost cannot be rebuilt" \
    resume "$tmp/g" --generations 6
  head -3 "$tmp/ref/generations.csv" > "$tmp/g/generations.csv"
  expect_bad "g/generations.csv holds 1 generation but the checkpoint 5: rows lost cannot be rebuilt" \
    resume "$tmp/g" --generations 6
  head -c -2 "$tmp/ref/generations.csv" > "$tmp/g/generations.csv" # generation 4's B row torn: lost (a row missing
  # only its newline is whole and repaired since issue 49: tools/safety3_messages)
  cp "$tmp/g/generations.csv" "$tmp/cut.csv"
  expect_bad "g/generations.csv holds 4 generations but the checkpoint 5: rows lost cannot be rebuilt" \
    resume "$tmp/g" --generations 6
  cmp "$tmp/cut.csv" "$tmp/g/generations.csv" || fail "a refused resume changed generations.csv"
  # the advice works: the run played again from its config.ini gives the same rows and the same checkpoint
  "$duel" run --config "$tmp/ref/config.ini" --out "$tmp/again" --quiet
  diff <(cut -d, -f1-16 "$tmp/ref/generations.csv") <(cut -d, -f1-16 "$tmp/again/generations.csv") ||
    fail "the run played again differs"
  cmp "$tmp/ref/checkpoint.bin" "$tmp/again/checkpoint.bin" || fail "the run played again has another checkpoint"
  # in an experiment: the report refuses, and deleting the run's directory then experiment resume repairs it
  "$duel" experiment "$plan" --out "$tmp/x" --set generations=2 --quiet > /dev/null
  cp "$tmp/x/report/table1.csv" "$tmp/table1.csv"
  cp -r "$tmp/x/runs/complexify-2" "$tmp/c2"
  sed -i 3d "$tmp/x/runs/complexify-2/generations.csv"
  expect_bad "complexify-2/generations.csv:3: .*rows are missing: .*delete the run's directory and duel_evolve experiment resume plays it again" \
    experiment report "$tmp/x"
  head -c -1 "$tmp/c2/generations.csv" > "$tmp/x/runs/complexify-2/generations.csv"
  expect_bad "generations.csv:[0-9]*: the last row is cut short (no newline): resuming the run cuts it" \
    experiment report "$tmp/x"
  rm -r "$tmp/x/runs/complexify-2"
  "$duel" experiment resume "$tmp/x" --quiet > /dev/null
  cmp "$tmp/c2/checkpoint.bin" "$tmp/x/runs/complexify-2/checkpoint.bin" || fail "the run played again differs"
  diff <(cut -d, -f1-4 "$tmp/table1.csv") <(cut -d, -f1-4 "$tmp/x/report/table1.csv") || fail "another table"
  # a cut dominance.csv in a finished experiment run: resume the run, as the message says
  head -c -1 "$tmp/c2/dominance.csv" > "$tmp/x/runs/complexify-2/dominance.csv"
  expect_bad "the last row is cut short (no newline): resuming the run rebuilds" experiment report "$tmp/x"
  "$duel" resume "$tmp/x/runs/complexify-2" --quiet
  "$duel" experiment report "$tmp/x" > /dev/null
  ;;
outputs)
  # class 1: an output that exists and is not recognisably this command's is refused (exit 2) unless --force; an
  # output that is one of the command's inputs is refused even then
  "$duel" run --config "$cfg" --out "$tmp/a" --generations 3 --quiet
  "$duel" run --config "$cfg" --out "$tmp/b" --generations 3 --seed 2 --quiet
  blob=$tmp/a/champions/gen-00001.blob
  printf 'my data\n' > "$tmp/mine.txt"
  cp "$tmp/a/checkpoint.bin" "$tmp/ckpt.keep"
  mine() { [ "$(cat "$tmp/mine.txt")" = "my data" ] || fail "$1 replaced a file that is not its output"; }
  # compare: the cache, the CSV, the JSON
  expect_bad "compare: --cache .*a/checkpoint.bin is a file of the run .*a it reads: refusing to write over it" \
    compare "$tmp/a" --against "$tmp/b" --cache "$tmp/a/checkpoint.bin" --force
  cmp -s "$tmp/ckpt.keep" "$tmp/a/checkpoint.bin" || fail "compare --cache replaced a checkpoint"
  expect_bad "compare: --cache .*mine.txt exists and is not a compare cache: refusing to replace it (--force replaces it)" \
    compare "$tmp/a" --against "$tmp/b" --cache "$tmp/mine.txt"
  mine "compare --cache"
  expect_bad "compare: --csv .*mine.txt exists and is not a compare CSV" compare "$tmp/a" --against "$tmp/b" --csv "$tmp/mine.txt"
  expect_bad "compare: --json .*mine.txt exists and is not a compare JSON file" \
    compare "$tmp/a" --against "$tmp/b" --json "$tmp/mine.txt"
  mine "compare --csv/--json"
  expect_bad "compare: --csv .*a/dominance.csv is a file of the run" compare "$tmp/a" --against "$tmp/b" --csv "$tmp/a/dominance.csv" --force
  expect_bad "compare: --csv .*c.csv is also one of its inputs or outputs" compare "$tmp/a" --against "$tmp/b" --csv "$tmp/c.csv" --json "$tmp/c.csv"
  "$duel" compare "$tmp/a" --against "$tmp/b" --csv "$tmp/c.csv" --json "$tmp/c.json" --cache "$tmp/cache.csv" > /dev/null
  "$duel" compare "$tmp/a" --against "$tmp/b" --csv "$tmp/c.csv" --json "$tmp/c.json" --cache "$tmp/cache.csv" > /dev/null ||
    fail "compare refused its own outputs"
  cp "$tmp/mine.txt" "$tmp/other.txt"
  "$duel" compare "$tmp/a" --against "$tmp/b" --cache "$tmp/other.txt" --force > /dev/null || fail "--force"
  head -1 "$tmp/other.txt" | grep -q "^# duel_evolve compare cache" || fail "--force did not replace the file"
  # the cache: a CRLF copy reads the same; two different results for one comparison, or a cut line, are refused
  sed 's/$/\r/' "$tmp/cache.csv" > "$tmp/crlf.csv"
  "$duel" compare "$tmp/a" --against "$tmp/b" --cache "$tmp/crlf.csv" | grep -q "(0 played, [1-9][0-9]* from the cache)" ||
    fail "a CRLF cache was not read"
  { cat "$tmp/cache.csv"; tail -1 "$tmp/cache.csv" | awk -F, -v OFS=, '{ $4 = $4 + 1; $5 = $5 - 1; print }'; } > "$tmp/dup.csv"
  expect_bad "dup.csv:[0-9]*: a second, different result for the comparison of" compare "$tmp/a" --against "$tmp/b" --cache "$tmp/dup.csv"
  head -c -3 "$tmp/cache.csv" > "$tmp/cut.csv" # (a last line missing only its newline is whole: taken, issue 49)
  expect_bad "cut.csv:[0-9]*: the last line is cut short" compare "$tmp/a" --against "$tmp/b" --cache "$tmp/cut.csv"
  # the per-run cache, and ladder's outputs
  cp "$tmp/mine.txt" "$tmp/b/compare-cache.csv"
  expect_bad "b/compare-cache.csv: not a compare cache this version reads" compare "$tmp/b" --against "$tmp/a"
  cmp -s "$tmp/mine.txt" "$tmp/b/compare-cache.csv" || fail "a foreign per-run cache was replaced"
  rm "$tmp/b/compare-cache.csv"
  expect_bad "ladder: --csv .*mine.txt exists and is not a ladder CSV" ladder "$tmp/a" --top --csv "$tmp/mine.txt"
  mine "ladder --csv"
  cp "$tmp/mine.txt" "$tmp/a/ladder.csv"
  expect_bad "ladder: its .*a/ladder.csv exists and is not a ladder CSV" ladder "$tmp/a"
  expect_bad "ladder: --csv .*a/generations.csv is a file of the run" ladder "$tmp/a" --csv "$tmp/a/generations.csv" --force
  "$duel" ladder "$tmp/a" --force > /dev/null
  "$duel" ladder "$tmp/a" > /dev/null || fail "ladder refused its own ladder.csv"
  # one-input commands: never over the input, never over a foreign file
  cp "$blob" "$tmp/in.blob"
  expect_bad "dot: -o .*in.blob is also one of its inputs or outputs" dot "$tmp/in.blob" -o "$tmp/in.blob" --force
  ln -s in.blob "$tmp/alias.blob"
  expect_bad "dot: -o .*alias.blob is also one of its inputs or outputs" dot "$tmp/in.blob" -o "$tmp/alias.blob" --force
  expect_bad "dot: -o .*mine.txt exists and is not a Graphviz file" dot "$tmp/in.blob" -o "$tmp/mine.txt"
  expect_bad "export: -o .*in.blob is also one of its inputs or outputs" export "$tmp/in.blob" --c-array x -o "$tmp/in.blob" --force
  expect_bad "export: -o .*x.c is also one of its inputs or outputs" export "$tmp/in.blob" --c-array x -o "$tmp/x.c" --header "$tmp/x.c"
  expect_bad "export: -o .*mine.txt exists and is not a C file from duel_evolve export" export "$tmp/in.blob" --c-array x -o "$tmp/mine.txt"
  expect_bad "export: -o .*mine.txt exists and is not a world's bytes" export --world v1 --raw -o "$tmp/mine.txt"
  cmp -s "$blob" "$tmp/in.blob" || fail "an input was changed"
  mine "dot/export"
  "$duel" export "$tmp/in.blob" --c-array x -o "$tmp/x.c" --header "$tmp/x.h"
  "$duel" export "$tmp/in.blob" --c-array x -o "$tmp/x.c" --header "$tmp/x.h" || fail "export refused its own files"
  "$duel" export --world v1 --raw -o "$tmp/w.bin" && "$duel" export --world v1 --raw -o "$tmp/w.bin" || fail "--raw twice"
  expect_bad "play: --trace .*in.blob is also one of its inputs or outputs" play "$tmp/in.blob" builtin:forager --trace "$tmp/in.blob" --force
  expect_bad "play: --trace .*mine.txt exists and is not a game trace" play "$tmp/in.blob" builtin:forager --trace "$tmp/mine.txt"
  expect_bad "play: --lcm-log .*mine.txt exists and is not this project's LCM event log" \
    play "$tmp/in.blob" builtin:forager --lcm-log "$tmp/mine.txt"
  expect_bad "node world: --lcm-log .*mine.txt exists and is not this project's LCM event log" \
    node world --food 3 --lcm memq:// --lcm-log "$tmp/mine.txt"
  mine "play/node"
  "$duel" play "$tmp/in.blob" builtin:forager --lcm-log "$tmp/g.lcm" > /dev/null
  "$duel" play "$tmp/in.blob" builtin:forager --lcm-log "$tmp/g.lcm" > /dev/null || fail "play refused its own log"
  # render: frames and the video
  mkdir "$tmp/frames"
  cp "$tmp/mine.txt" "$tmp/frames/frame-00002.png"
  expect_bad "render: --out .*frames/frame-00002.png exists and is not a frame from duel_evolve render" \
    render "$tmp/in.blob" builtin:forager --out "$tmp/frames" --every 300
  [ "$(ls "$tmp/frames")" = frame-00002.png ] || fail "render wrote frames before refusing: $(ls "$tmp/frames")"
  rm "$tmp/frames/frame-00002.png"
  "$duel" render "$tmp/in.blob" builtin:forager --out "$tmp/frames" --every 300 > /dev/null
  "$duel" render "$tmp/in.blob" builtin:forager --out "$tmp/frames" --every 300 > /dev/null || fail "render refused its frames"
  if command -v ffmpeg > /dev/null; then
    expect_bad "render: --video .*mine.txt exists and is not a video from duel_evolve render" \
      render "$tmp/in.blob" builtin:forager --out "$tmp/frames" --every 300 --video "$tmp/mine.txt"
    mine "render --video"
    "$duel" render "$tmp/in.blob" builtin:forager --out "$tmp/frames" --every 300 --video "$tmp/v.mp4" > /dev/null
    "$duel" render "$tmp/in.blob" builtin:forager --out "$tmp/frames" --every 300 --video "$tmp/v.mp4" > /dev/null ||
      fail "render refused its own video"
  fi
  ;;
paths)
  # class 5: a relative start path in a plan is the plan's, resolved once when the plan is read; control
  # characters in a start path are refused
  presets=$(cd "$(dirname "$plan")/../../configs" && pwd)
  "$duel" run --config "$cfg" --out "$tmp/src" --generations 2 --quiet
  mkdir -p "$tmp/plans" "$tmp/elsewhere"
  cp "$tmp/src/champions/gen-00001.genome" "$tmp/plans/start.genome"
  printf '[experiment]\npresets = %s\n[all runs]\ngenerations = 1\npop_size = 16\ncompare_configs = 12\n[method c]\npreset = paper\nruns = 2\nstart = genome:start.genome\n' \
    "$presets" > "$tmp/plans/p.ini"
  # a same-named file where the runs work is not the one used
  (cd "$tmp/elsewhere" && printf 'not a genome\n' > start.genome &&
    "$duel" experiment ../plans/p.ini --out "$tmp/x2" --quiet > /dev/null) ||
    fail "a plan's relative start path did not resolve from another directory"
  grep -q "start = genome:$tmp/plans/start.genome" "$tmp/x2/plan.ini" || fail "plan.ini: $(grep start "$tmp/x2/plan.ini")"
  grep -q "^start = genome:$tmp/plans/start.genome" "$tmp/x2/runs/c-1/config.ini" || fail "the run's start path"
  "$duel" experiment resume "$tmp/x2" --quiet > /dev/null || fail "resume of a plan with a start path"
  rm "$tmp/plans/start.genome"
  expect_bad "start=genome:.*start.genome (relative to .*plans): No such file or directory" \
    experiment "$tmp/plans/p.ini" --out "$tmp/x3"
  [ ! -e "$tmp/x3" ] || fail "a plan with a missing start file made its directory"
  # on the command line, a path is the working directory's
  cp "$tmp/src/champions/gen-00001.genome" "$tmp/elsewhere/s2.genome"
  sed -i '/^start = /d' "$tmp/plans/p.ini"
  (cd "$tmp/elsewhere" && "$duel" experiment ../plans/p.ini --out "$tmp/x4" --set start=genome:s2.genome --quiet > /dev/null) ||
    fail "--set start=genome:RELATIVE"
  grep -q "start = genome:$tmp/elsewhere/s2.genome" "$tmp/x4/plan.ini" || fail "plan.ini: $(grep start "$tmp/x4/plan.ini")"
  expect_bad "start: a control character (byte 0x0a)" run --config "$cfg" --out "$tmp/never" --set "start=genome:a
b"
  expect_bad "start: a control character (byte 0x09)" run --config "$cfg" --out "$tmp/never" --set "start=blob:a	b"
  [ ! -e "$tmp/never" ] || fail "a refused start path made the run directory"
  ;;
edits)
  # class 6: a hand edit of what a run or an experiment was made with is refused, never silently taken or ignored
  "$duel" run --config "$cfg" --out "$tmp/r" --generations 2 --quiet
  cp "$tmp/r/config.ini" "$tmp/config.keep"
  sed -i 's/^weight_mut_prob = .*/weight_mut_prob = 0.5/' "$tmp/r/config.ini"
  expect_bad "r/config.ini says 'weight_mut_prob = 0.5' but the run in its checkpoint has 'weight_mut_prob = 0.8': a hand edit" \
    resume "$tmp/r" --generations 3
  "$duel" resume "$tmp/r" --generations 3 --set weight_mut_prob=0.5 --quiet || fail "the same change as --set"
  grep -q "resume: override weight_mut_prob=0.5" "$tmp/r/log.txt" || fail "the override not logged"
  "$duel" resume "$tmp/r" --generations 4 --quiet || fail "resume after an override"
  head -20 "$tmp/r/config.ini" > "$tmp/cut.ini"
  cp "$tmp/r/config.ini" "$tmp/whole.ini"
  cp "$tmp/cut.ini" "$tmp/r/config.ini"
  expect_bad "r/config.ini says '.*' but the run in its checkpoint has '.*': a hand edit" resume "$tmp/r" --generations 5
  cp "$tmp/whole.ini" "$tmp/r/config.ini"
  # a run against fixed opponents too
  "$duel" run --config "$cfg" --out "$tmp/f" --generations 2 --set opponents.play=builtin:forager --quiet
  sed -i 's/^c1 = .*/c1 = 2.5/' "$tmp/f/config.ini"
  expect_bad "f/config.ini says 'c1 = 2.5' but the run in its checkpoint has 'c1 = 1': a hand edit" resume "$tmp/f" --generations 3
  # an experiment: plan.ini and configs/ against what the runs were made with
  "$duel" experiment "$plan" --out "$tmp/x" --set generations=2 --quiet > /dev/null
  cp "$tmp/x/plan.ini" "$tmp/plan.keep"
  sed -i 's/^generations = 2/generations = 3/' "$tmp/x/plan.ini"
  expect_bad "configs/complexify.ini says 'generations = 2' but plan.ini makes 'generations = 3' (line 3): the plan of an experiment cannot change" \
    experiment resume "$tmp/x"
  cp "$tmp/plan.keep" "$tmp/x/plan.ini"
  # a changed preset name (its report would name a preset the runs were not made from)
  sed -i 's/^preset = fixed-5/preset = fixed-10/' "$tmp/x/plan.ini"
  expect_bad "plan.ini says preset = fixed-10 but .*x/configs/fixed-5.ini was made from preset fixed-5: the plan of an experiment cannot change" \
    experiment resume "$tmp/x"
  cp "$tmp/plan.keep" "$tmp/x/plan.ini"
  "$duel" experiment resume "$tmp/x" --quiet > /dev/null # restored: taken again
  sed -i 's/^weight_mut_prob = .*/weight_mut_prob = 0.5/' "$tmp/x/configs/fixed-5.ini"
  expect_bad "runs/fixed-5-[12]/config.ini belongs to another plan" experiment resume "$tmp/x"
  ;;
counters)
  # class 8: a start genome whose node ids or innovation numbers leave the run no room is refused at load, naming
  # the genome (it used to pass every check and stop after generation 0 with a message about blob formats)
  "$duel" run --config "$cfg" --out "$tmp/src" --generations 1 --set start=hidden:2:inputs --quiet
  for field in innov node; do
    python3 - "$tmp/src/champions/gen-00000.genome" "$tmp/$field.genome" "$field" <<'PY'
import struct, sys, zlib
b = bytearray(open(sys.argv[1], "rb").read()[:-4])
at = 20  # magic, version, inputs, outputs; format 2 then the step and the run's tag (docs/formats.md)
if b[8] == 2:
    at = 28 + struct.unpack_from("<I", b, 24)[0]
n_nodes = struct.unpack_from("<I", b, at)[0]
if sys.argv[3] == "node":  # the last node, a hidden one, renumbered near 2^31 (its connections follow it)
    last = at + 4 + 5 * (n_nodes - 1)
    old = struct.unpack_from("<I", b, last)[0]
    struct.pack_into("<I", b, last, 0x7FFFFFF0)
    c_at = at + 4 + 5 * n_nodes
    for k in range(struct.unpack_from("<I", b, c_at)[0]):
        for off in (0, 4):
            if struct.unpack_from("<I", b, c_at + 4 + 21 * k + off)[0] == old:
                struct.pack_into("<I", b, c_at + 4 + 21 * k + off, 0x7FFFFFF0)
else:  # the last connection's innovation number
    c_at = at + 4 + 5 * n_nodes
    n = struct.unpack_from("<I", b, c_at)[0]
    struct.pack_into("<I", b, c_at + 4 + 21 * (n - 1) + 8, 0x7FFFFFF0)
open(sys.argv[2], "wb").write(bytes(b) + struct.pack("<I", zlib.crc32(bytes(b))))
PY
    "$duel" inspect "$tmp/$field.genome" > /dev/null || fail "the crafted $field genome does not load"
    expect_bad "$field.genome: start genome with .* 2147483632, more than 1073741823: it would leave the run too few" \
      run --config "$cfg" --out "$tmp/never-$field" --set "start=genome:$tmp/$field.genome"
  done
  ;;
small)
  # class 10: CSV quoting, a cache saved as compare goes and merged under a lock, names escaped, file: paths for
  # ffmpeg. SHIM (the 5th argument) is tests/tools/fault_shim.c, whose trace counts the cache's renames.
  shim=$5
  # under the sanitizer build the shim comes before libasan: tell ASan that is fine
  export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"
  cd "$tmp"
  for s in 1 2 3 4 5 6 7 8; do "$duel" run --config "$cfg" --generations 12 --seed "$s" --out "r$s" --quiet; done
  mv r1 "r,1"
  "$duel" compare "r,1" r2 --against "r,1" r2 r3 --csv q.csv > /dev/null
  python3 -c 'import csv, sys
rows = list(csv.reader(open("q.csv")))
assert all(len(r) == 15 for r in rows), rows  # wins, then world and both steps (issue 49)
assert sorted(r[0] for r in rows[1:]) == ["r,1", "r,1", "r2", "r2"], rows' || fail "compare --csv: $(cat q.csv)"
  mv "r,1" r1
  # every chunk of comparisons is saved at once: a killed compare keeps what it played
  all="r1 r2 r3 r4 r5 r6 r7 r8"
  # shellcheck disable=SC2086
  NEAT_FAULT_TRACE="$tmp/trace" LD_PRELOAD="$shim" "$duel" compare $all --against $all --threads 1 --cache c.csv > c.txt
  n=$(grep -c "^rename .*c.csv$" "$tmp/trace" || true)
  jobs=$(sed -n 's/.*, \([0-9]*\) comparisons of 288 games.*/\1/p' c.txt)
  [ "$jobs" -gt 64 ] || fail "too few comparisons to test the saving: $(head -1 c.txt)"
  [ "$n" -ge 3 ] || fail "the cache was saved $n times for $jobs comparisons (once a chunk of at most 32 expected)"
  # two compares of one cache at once lose nothing (merged under c2.csv.lock)
  # shellcheck disable=SC2086
  "$duel" compare r1 r2 r3 r4 --against $all --cache c2.csv > /dev/null &
  p1=$!
  # shellcheck disable=SC2086
  "$duel" compare r5 r6 r7 r8 --against $all --cache c2.csv > /dev/null
  wait "$p1"
  [ "$(sort c.csv | md5sum)" = "$(sort c2.csv | md5sum)" ] || fail "concurrent compares lost cache entries"
  # names from LCM messages (here a file name) are printed with control bytes escaped: one line stays one line
  cp r2/champions/gen-00003.blob "a
b.blob"
  "$duel" play "a
b.blob" builtin:forager --lcm-log g.lcm > /dev/null
  "$duel" log info g.lcm > info.txt
  grep -q 'west a\\x0ab.blob, east' info.txt || fail "log info: $(grep game: info.txt)"
  # ffmpeg reads the frames through file: (a directory named like a URL is never fetched)
  if command -v ffmpeg > /dev/null; then
    "$duel" render builtin:idle builtin:forager --out "http://127.0.0.1:9/f" --every 300 --video v.mp4 > /dev/null ||
      fail "render into a directory named like a URL"
    [ -s v.mp4 ] || fail "no video"
  fi
  ;;
*)
  fail "unknown check $what"
  ;;
esac
echo "safety $what: ok"
