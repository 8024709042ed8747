#!/usr/bin/env bash
# safety3.sh DUEL_EVOLVE CONFIG PLAN CHECK - data safety, third pass (issue 49; docs/hardening.md): no output reaches
# a run's own files, --force included; a plan is checked whole; one policy for edits. Each case failed before it.
# CONFIG is a small run (tests/tools/coev-small.ini), PLAN a small experiment (tests/tools/tiny-plan.ini).
set -euo pipefail
duel=$1 cfg=$2 plan=$3 what=$4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=/dev/null
. "$(dirname "$0")/cli_lib.sh"
snapshot() { (cd "$1" && find . -type f ! -name .lock -print0 | sort -z | xargs -0 md5sum); }

case "$what" in
runfiles)
  # §2: an output path that is a file of any run or experiment directory is refused with exit 2, --force or not,
  # and the refusal does not suggest --force
  "$duel" run --config "$cfg" --out "$tmp/r" --generations 2 --quiet
  cp "$tmp/r/champions/gen-00001.blob" "$tmp/in.blob"
  before=$(snapshot "$tmp/r")
  for f in checkpoint.bin config.ini generations.csv dominance.csv log.txt champions/gen-00000.blob; do
    for force in "" --force; do
      expect_bad "play: --trace .*r/$f is a file of the run directory .*r: refusing to write there (choose a path outside it)" \
        play "$tmp/in.blob" builtin:forager --trace "$tmp/r/$f" $force
      expect_bad "play: --lcm-log .*r/$f is a file of the run directory" play "$tmp/in.blob" builtin:forager --lcm-log "$tmp/r/$f" $force
      expect_bad "dot: -o .*r/$f is a file of the run directory" dot "$tmp/in.blob" -o "$tmp/r/$f" $force
      expect_bad "export: -o .*r/$f is a file of the run directory" export "$tmp/in.blob" --c-array x -o "$tmp/r/$f" $force
      expect_bad "export: --header .*r/$f is a file of the run directory" \
        export "$tmp/in.blob" --c-array x -o "$tmp/x.c" --header "$tmp/r/$f" $force
      expect_bad "render-net: --out .*r/$f is a file of the run directory" render-net "$tmp/in.blob" --out "$tmp/r/$f" $force
      expect_bad "node world: --lcm-log .*r/$f is a file of the run directory" \
        node world --food 3 --lcm memq:// --lcm-log "$tmp/r/$f" $force
    done
  done
  if command -v ffmpeg > /dev/null; then
    expect_bad "render: --video .*r/checkpoint.bin is a file of the run directory" \
      render "$tmp/in.blob" builtin:forager --out "$tmp/frames" --every 300 --video "$tmp/r/checkpoint.bin" --force
  fi
  # a champion file that does not exist yet is a run's file too (the run writes it next generation)
  expect_bad "dot: -o .*r/champions/gen-00009.blob is a file of the run directory" dot "$tmp/in.blob" -o "$tmp/r/champions/gen-00009.blob"
  [ "$(snapshot "$tmp/r")" = "$before" ] || fail "a run's files changed"
  # an experiment's run: ladder --world X --csv RUN/ladder.csv is refused, and so is its plan or report
  "$duel" experiment "$plan" --out "$tmp/e" --set generations=1 --quiet > /dev/null
  run1=$(ls -d "$tmp/e/runs/"*-1 | head -1)
  ebefore=$(snapshot "$tmp/e")
  expect_bad "ladder: --csv .*ladder.csv is a file of the run directory" ladder "$run1" --top --world "$(dirname "$0")/fixtures/world-variant.ini" --csv "$run1/ladder.csv" --force
  expect_bad "ladder: --csv .*e/plan.ini is a file of the experiment directory" ladder "$run1" --top --csv "$tmp/e/plan.ini" --force
  expect_bad "dot: -o .*e/report/table1.csv is a file of the experiment directory" dot "$tmp/in.blob" -o "$tmp/e/report/table1.csv" --force
  expect_bad "dot: -o .*e/configs/x.ini is a file of the experiment directory" dot "$tmp/in.blob" -o "$tmp/e/configs/x.ini"
  [ "$(snapshot "$tmp/e")" = "$ebefore" ] || fail "an experiment's files changed"
  # what still works: a run's own ladder, and outputs beside (not inside) a run's files
  "$duel" ladder "$run1" --top > /dev/null || fail "ladder refused the run's own ladder.csv"
  "$duel" dot "$tmp/in.blob" -o "$tmp/r/notes.dot" || fail "a file of another name in a run directory"
  ;;
dirs)
  # §2: run --out refuses a non-empty directory that is not a run it made; an output directory given as a file (or
  # a file in a missing directory) is refused before any game; render --out keeps one game's frames only
  for f in generations.csv dominance.csv strength.csv; do
    mkdir "$tmp/u-$f"
    printf 'generation,mine\n1,2\n' > "$tmp/u-$f/$f"
    expect_bad "u-$f is not empty and not a run directory (it holds '$f' but no config.ini of a run): choose another --out" \
      run --config "$cfg" --out "$tmp/u-$f" --generations 1
    [ "$(cat "$tmp/u-$f/$f")" = "$(printf 'generation,mine\n1,2')" ] || fail "run --out replaced the user's $f"
    [ "$(ls -A "$tmp/u-$f")" = "$f" ] || fail "run --out left files in the user's directory: $(ls -A "$tmp/u-$f")"
  done
  "$duel" run --config "$cfg" --out "$tmp/r" --generations 2 --quiet
  "$duel" run --config "$cfg" --out "$tmp/s" --generations 2 --seed 2 --quiet
  mkdir "$tmp/d"
  expect_bad "ladder: --csv .*d is a directory: name a file" ladder "$tmp/r" --csv "$tmp/d"
  expect_bad "compare: --csv .*d is a directory: name a file" compare "$tmp/r" --against "$tmp/s" --csv "$tmp/d"
  expect_bad "compare: --json .*d is a directory: name a file" compare "$tmp/r" --against "$tmp/s" --json "$tmp/d"
  expect_bad "ladder: --csv .*nowhere/x.csv: cannot write: .*nowhere does not exist" ladder "$tmp/r" --csv "$tmp/nowhere/x.csv"
  printf 'x\n' > "$tmp/file"
  expect_bad "compare: --csv .*file/x.csv: cannot write: .*file is not a directory" compare "$tmp/r" --against "$tmp/s" --csv "$tmp/file/x.csv"
  expect_bad "play: --trace .*d is a directory: name a file" play "$tmp/r/champions/gen-00001.blob" builtin:forager --trace "$tmp/d"
  [ ! -e "$tmp/r/compare-cache.csv" ] && [ ! -e "$tmp/r/ladder.csv" ] || fail "games were played before the refusal"
  # render --out: a directory holding anything but frames is refused; an earlier, longer game's frames are removed
  blob=$tmp/r/champions/gen-00001.blob
  expect_bad "render: --out .*file/frame-00000.png: cannot write: .*file is not a directory" render "$blob" builtin:forager --out "$tmp/file" --every 300
  mkdir "$tmp/fr"
  printf 'notes\n' > "$tmp/fr/notes.txt"
  expect_bad "render: --out .*fr holds 'notes.txt', which is not a frame of duel_evolve render" \
    render "$blob" builtin:forager --out "$tmp/fr" --every 300
  [ "$(ls -A "$tmp/fr")" = notes.txt ] || fail "render wrote into a directory holding others"
  expect_bad "render: --out .*r holds '.*', which is not a frame" render "$blob" builtin:forager --out "$tmp/r" --every 300
  rm "$tmp/fr/notes.txt"
  "$duel" render "$blob" builtin:forager --out "$tmp/fr" --every 10 > /dev/null
  many=$(ls "$tmp/fr" | wc -l)
  "$duel" render "$blob" builtin:forager --out "$tmp/fr" --every 300 > "$tmp/out"
  few=$(ls "$tmp/fr" | wc -l)
  grep -q "^$few frames of" "$tmp/out" || fail "render left other frames: $few files, $(grep frames "$tmp/out")"
  [ "$many" -gt "$few" ] || fail "the test's first render was not longer ($many, $few)"
  ;;
world)
  # §1: [world] rules = applies first wherever it stands (in a file, in --set lists); the section takes the one
  # number syntax of every INI key
  printf '[world]\nfood_range = 300\nrules = v1\n' > "$tmp/w.ini"
  "$duel" config --config "$tmp/w.ini" --dump > "$tmp/d1"
  grep -q "^food_range = 300$" "$tmp/d1" || fail "an override before rules = was dropped: $(grep food_range "$tmp/d1")"
  printf '[world]\nrules = v1\nfood_range = 300\n' > "$tmp/w2.ini"
  "$duel" config --config "$tmp/w2.ini" --dump > "$tmp/d2"
  cmp -s "$tmp/d1" "$tmp/d2" || fail "rules = before or after an override differ"
  "$duel" config --config "$cfg" --set world.food_range=300 --set world.rules=v1 --dump > "$tmp/d3"
  grep -q "^food_range = 300$" "$tmp/d3" || fail "--set world.rules= after an override dropped it"
  for v in 0x100 1e3 +300 300.0 ' 3e2'; do
    printf '[world]\nfood_range = %s\n' "$v" > "$tmp/n.ini"
    expect_bad "n.ini:2: \[world\] food_range = '.*': expected a whole number of units" config --config "$tmp/n.ini" --dump
  done
  for v in 0x10 inf nan 1e 0x1p3; do
    printf '[world]\nradius = %s\n' "$v" > "$tmp/n.ini"
    expect_bad "n.ini:2: \[world\] radius = '$v': expected a number" config --config "$tmp/n.ini" --dump
    printf '[world]\nstart_west = %s 0 0\n' "$v" > "$tmp/n.ini"
    expect_bad "n.ini:2: \[world\] start_west = '$v 0 0': expected x y heading" config --config "$tmp/n.ini" --dump
  done
  # what the syntax allows: signs, points and exponents in real keys
  printf '[world]\nradius = +1.25e1\nstart_west = +100 .3e3 -90\n' > "$tmp/ok.ini"
  "$duel" config --config "$tmp/ok.ini" --dump | grep -q "^radius = 12.5$" || fail "a real in the common syntax"
  ;;
plan)
  # §3, §4: a plan's seed is refused or honoured, never ignored; a plan is checked whole before its first run
  presets=$(cd "$(dirname "$plan")/../../configs" && pwd)
  mkdir -p "$tmp/plans"
  base() { printf '[experiment]\npresets = %s\nseed = 3\n[all runs]\ngenerations = 1\npop_size = 16\ncompare_configs = 12\n' "$presets"; }
  { base; printf 'seed = 7\n[method c]\npreset = paper\nruns = 2\n'; } > "$tmp/plans/s1.ini"
  expect_bad "s1.ini:8: seed = 7: the runs of an experiment take their seeds from \[experiment\] seed" experiment "$tmp/plans/s1.ini" --dry-run
  { base; printf '[method c]\npreset = paper\nruns = 2\nrun.seed = 7\n'; } > "$tmp/plans/s2.ini"
  expect_bad "s2.ini:11: run.seed = 7: the runs of an experiment take their seeds" experiment "$tmp/plans/s2.ini" --out "$tmp/never"
  [ ! -e "$tmp/never" ] || fail "a refused plan made its directory"
  { base; printf '[method c]\npreset = paper\nruns = 2\n'; } > "$tmp/plans/ok.ini"
  "$duel" experiment "$tmp/plans/ok.ini" --out "$tmp/x" --set seed=40 --quiet > /dev/null 2>&1
  grep -q "^seed = 40$" "$tmp/x/plan.ini" || fail "--set seed= was not the experiment's seed: $(grep seed "$tmp/x/plan.ini")"
  grep -q "^seed = 40$" "$tmp/x/runs/c-1/config.ini" && grep -q "^seed = 41$" "$tmp/x/runs/c-2/config.ini" ||
    fail "--set seed= did not reach the runs"
  "$duel" experiment resume "$tmp/x" --quiet > /dev/null 2>&1 || fail "resume of a plan given --set seed="
  # a start genome that is not one is refused before any run (and by --dry-run)
  printf 'junk\n' > "$tmp/plans/bad.genome"
  { base; printf '[method c]\npreset = paper\nruns = 2\nstart = genome:bad.genome\n'; } > "$tmp/plans/g.ini"
  expect_bad "experiment: \[method c\]: .*bad.genome: not a valid genome file" experiment "$tmp/plans/g.ini" --dry-run
  expect_bad "experiment: \[method c\]: .*bad.genome: not a valid genome file" experiment "$tmp/plans/g.ini" --out "$tmp/never"
  [ ! -e "$tmp/never" ] || fail "a plan with a bad start genome made its directory"
  # a method that cannot be measured: against fixed opponents, or in another world
  { base; printf '[method c]\npreset = paper\nruns = 2\n[method v]\npreset = vs-forager-hunter\nruns = 1\n'; } > "$tmp/plans/f.ini"
  expect_bad "\[method v\]: a run against fixed opponents (\[opponents\] play) has no dominance tournament" \
    experiment "$tmp/plans/f.ini" --dry-run
  cp "$(dirname "$0")/fixtures/world-variant.ini" "$tmp/plans/w.ini"
  { base; printf '[method c]\npreset = paper\nruns = 2\n[method w]\npreset = paper\nruns = 1\nfood_range = 300\n'; } > "$tmp/plans/w2.ini"
  expect_bad "\[method w\] plays in world custom [0-9a-f]* but \[method c\] in world v1: an experiment compares its methods in one world" \
    experiment "$tmp/plans/w2.ini" --dry-run
  # [opponents] play: a relative path is the plan's (never a same-named file where the runs work), control
  # characters are refused
  mkdir "$tmp/work"
  "$duel" run --config "$cfg" --out "$tmp/src" --generations 2 --quiet
  { base; printf '[method c]\npreset = paper\nruns = 2\nplay = opp.blob, builtin:idle\n'; } > "$tmp/plans/o.ini"
  (cd "$tmp/work" && cp "$tmp/src/champions/gen-00001.blob" opp.blob &&
    expect_bad "play: opp.blob (relative to .*plans): No such file or directory" experiment ../plans/o.ini --dry-run)
  expect_bad "play: a control character (byte 0x0a) at offset 1 of its value" run --config "$cfg" --out "$tmp/never" \
    --set "play=a
b"
  # compare and ladder name a fixed-opponent run's checkpoint for what it is
  "$duel" run --config "$presets/vs-forager-hunter.ini" --set pop_size=16 --generations 1 --out "$tmp/fx" --quiet
  expect_bad "fx/checkpoint.bin: the checkpoint of a run against fixed opponents (one population, no dominance tournament)" \
    compare "$tmp/fx" --against "$tmp/src"
  expect_bad "fx/checkpoint.bin: the checkpoint of a run against fixed opponents" compare "$tmp/src" --against "$tmp/fx"
  expect_bad "fx/checkpoint.bin: the checkpoint of a run against fixed opponents" ladder "$tmp/fx" --top
  ;;
scripts)
  # §5: the study scripts take their output directory's lock, never count a cut row as a finished run, and never
  # remove a run directory; study_summary.py refuses duplicate and cut rows with a message
  root=$(cd "$(dirname "$0")/../.." && pwd)
  export DUEL_EVOLVE=$duel
  mkdir "$tmp/st"
  exec 8> "$tmp/st/.study_m1.lock"
  flock -n 8
  rc=0
  msg=$("$root/scripts/study_m1.sh" "$tmp/st" v1 2>&1 >/dev/null) || rc=$?
  [ $rc -eq 2 ] && printf '%s\n' "$msg" | grep -q "st is in use by another study_m1.sh" || fail "a second study_m1.sh: $rc $msg"
  exec 8>&-
  header="cell,opponent,seed,wins,losses,draws,timeouts,margin,champion_hidden,champion_connections,run_seconds"
  printf '%s\nv1,forager-hunter,1,100,150' "$header" > "$tmp/st/m1.csv"
  mkdir -p "$tmp/st/v1/forager-hunter-1"
  printf 'mine\n' > "$tmp/st/v1/forager-hunter-1/notes.txt"
  rc=0
  msg=$("$root/scripts/study_m1.sh" "$tmp/st" v1 2>&1 >/dev/null) || rc=$?
  [ $rc -eq 2 ] && printf '%s\n' "$msg" | grep -q "the row of v1 forager-hunter seed 1 is cut short" ||
    fail "a cut row counted as a finished run: $rc $msg"
  [ -f "$tmp/st/v1/forager-hunter-1/notes.txt" ] || fail "study_m1.sh removed a directory"
  # study_summary.py: cut, short, duplicate rows
  printf '%s\nv1,forager,1,1,2,0,285,-1,0,36,5.0\nv1,forager,1,1,2,0,285,-1,0,36,5.0\n' "$header" > "$tmp/dup.csv"
  printf '%s\nv1,forager,1,1,2,0,285,-1,0,36,5.0\nv1,forager,2,1,2\n' "$header" > "$tmp/short.csv"
  printf '%s\nv1,forager,1,1,2,0,285,-1,0,36,5.0' "$header" > "$tmp/cut.csv"
  for f in dup:"dup.csv:3: cell v1, opponent forager, seed 1 a second time (first on line 2)" \
           short:"short.csv:3: 5 fields, expected 11: a cut or edited row" \
           cut:"cut.csv: the last line is cut short (no newline)"; do
    rc=0
    msg=$(python3 "$root/scripts/study_summary.py" "$tmp/${f%%:*}.csv" 2>&1) || rc=$?
    [ $rc -ne 0 ] && ! printf '%s\n' "$msg" | grep -q Traceback && printf '%s\n' "$msg" | grep -qF "${f#*:}" ||
      fail "study_summary.py ${f%%:*}: $rc $msg"
  done
  printf '%s\nv1,forager,1,1,2,0,285,-1,0,36,5.0\r\n' "$header" > "$tmp/ok.csv"
  python3 "$root/scripts/study_summary.py" "$tmp/ok.csv" | grep -q "| v1 | forager | -1 |" || fail "a good table"
  ;;
messages)
  # §6: a missing final newline is repaired, not answered with "replay the whole run" or "delete the cache";
  # duplicated and CRLF rows are named as such; DUEL_MPI_WAIT refuses what it cannot parse
  "$duel" run --config "$cfg" --out "$tmp/r" --generations 3 --quiet
  cp -r "$tmp/r" "$tmp/full"
  "$duel" resume "$tmp/full" --generations 4 --quiet
  truncate -s -1 "$tmp/r/generations.csv"
  "$duel" resume "$tmp/r" --generations 4 --quiet || fail "resume refused generations.csv missing its last newline"
  cmp -s "$tmp/r/checkpoint.bin" "$tmp/full/checkpoint.bin" || fail "the repaired run differs"
  [ "$(cut -d, -f1-16 "$tmp/r/generations.csv")" = "$(cut -d, -f1-16 "$tmp/full/generations.csv")" ] ||
    fail "the repaired generations.csv differs"
  grep -q "generations.csv's last row lacked its newline (the row is whole): added" "$tmp/r/log.txt" || fail "not logged"
  cp -r "$tmp/full" "$tmp/dup"
  sed -i '3p' "$tmp/dup/generations.csv"
  expect_bad "dup/generations.csv:4: the row before again (a duplicated row): delete one of the two$" resume "$tmp/dup" --generations 5
  cp -r "$tmp/full" "$tmp/crlf"
  sed -i 's/$/\r/' "$tmp/crlf/generations.csv"
  expect_bad "crlf/generations.csv:1: a CRLF line end (a copy converted by a tool that writes Windows line ends): convert it back (dos2unix), the data is the same$" \
    resume "$tmp/crlf" --generations 5
  sed -i '3p' "$tmp/dup/dominance.csv"
  expect_bad "dup/dominance.csv:4: the row before again (a duplicated row)" ladder "$tmp/dup" --top
  # the compare cache: a last entry without its newline is whole, taken, and written back whole
  "$duel" run --config "$cfg" --out "$tmp/s" --generations 3 --seed 2 --quiet
  "$duel" compare "$tmp/full" --against "$tmp/s" --cache "$tmp/cache.csv" > /dev/null
  truncate -s -1 "$tmp/cache.csv"
  "$duel" compare "$tmp/full" --against "$tmp/s" --cache "$tmp/cache.csv" > "$tmp/out" ||
    fail "compare refused a cache missing its last newline"
  grep -q "(0 played, [1-9][0-9]* from the cache)" "$tmp/out" || fail "the cache was not used: $(cat "$tmp/out")"
  [ "$(tail -c 1 "$tmp/cache.csv" | od -An -c | tr -d ' ')" = '\n' ] || fail "the cache was not written back whole"
  # a name with control bytes is echoed escaped: one line whatever it holds
  expect_bad 'dot: -o .*no\\x0adir/x.dot: cannot write: .*no\\x0adir does not exist' \
    dot "$tmp/full/champions/gen-00001.blob" -o "$tmp/no
dir/x.dot"
  if command -v mpirun > /dev/null; then
    for v in abc 0x10 inf 0 -5 1e7; do
      rc=0
      DUEL_MPI_WAIT=$v mpirun --oversubscribe --allow-run-as-root -np 2 "$duel" run --config "$cfg" --out "$tmp/mpi" \
        --generations 1 --quiet > "$tmp/mout" 2>&1 || rc=$?
      ! grep -q "built without MPI" "$tmp/mout" || break # (the sanitizer build has no MPI)
      [ $rc -ne 0 ] && grep -q "DUEL_MPI_WAIT='$v': expected seconds" "$tmp/mout" || fail "DUEL_MPI_WAIT=$v: $rc $(cat "$tmp/mout")"
      [ ! -e "$tmp/mpi/checkpoint.bin" ] || fail "DUEL_MPI_WAIT=$v: a run was played"
    done
  fi
  # every value echoed in a message has its control bytes escaped: one message stays one line, and no escape
  # sequence reaches the terminal (arguments), or it is refused where it is read (an INI line)
  expect_bad "play: --games takes 1 or 288, not '2\\\\x1b\[31m88'" play builtin:idle builtin:idle --games $'2\e[31m88'
  msg=$("$duel" $'bo\ngus' 2>&1 > /dev/null || true)
  [ "$(printf '%s\n' "$msg" | head -1)" = "duel_evolve: unknown command 'bo\x0agus'" ] || fail "unknown command: $msg"
  expect_bad "run: unknown option '--bad\\\\x0ax'" run $'--bad\nx'
  expect_bad "ladder: unknown option '--x\\\\x07'" ladder "$tmp/r" $'--x\a'
  # a champion path is echoed escaped (a file whose name holds a newline is still played: tools/safety_small)
  expect_bad "duel_evolve: .*no\\\\x0afile.blob: cannot open: No such file or directory" play "$tmp/no"$'\n'"file.blob" builtin:idle
  printf 'NEATGENM' > "$tmp/cut"$'\r'".genome"
  expect_bad "cut\\\\x0d.genome: not a valid genome file" play "$tmp/cut"$'\r'".genome" builtin:idle
  expect_bad "--set hof_opponents=.*: hof_opponents: a control character (byte 0x1b) in its value" \
    config --dump --set $'hof_opponents=6\e[31m'
  # every other message that echoes a path escapes it too (a run, a configuration, a plan, an output, a log)
  nl=$'\n'
  expect_bad "r\\\\x0ax/dominance.csv: cannot open" ladder "$tmp/r${nl}x"
  expect_bad "a\\\\x1b\[31m.ini: cannot open" run --config "$tmp/a"$'\e'"[31m.ini" --out "$tmp/zz"
  expect_bad "compare: .*r\\\\x0ax: not a run directory" compare "$tmp/r${nl}x" --against "$tmp/s${nl}y"
  expect_bad "experiment: .*p\\\\x0a.ini: cannot open" experiment "$tmp/p${nl}.ini" --out "$tmp/qq"
  expect_bad "r\\\\x0ax/config.ini: cannot open" resume "$tmp/r${nl}x"
  expect_bad "render: .*e\\\\x0ax.lcm: cannot open" render "$tmp/e${nl}x.lcm" --out "$tmp/fr9"
  expect_bad "e\\\\x0ax.lcm: cannot open" log info "$tmp/e${nl}x.lcm"
  expect_bad "--trace .*nodir\\\\x0a/t.csv: cannot write: .*nodir\\\\x0a does not exist" \
    play builtin:idle builtin:idle --food 1 --trace "$tmp/nodir${nl}/t.csv"
  printf '[neat]\npop_size = 1\033[31m\n' > "$tmp/c.ini"
  expect_bad "c.ini:2: a control character (byte 0x1b) at column 13" config --config "$tmp/c.ini" --dump
  ;;
edits)
  # §3: one policy for edits. config.ini carries the run's seal: a hand edit of any key is refused (generations and
  # strength_every, which the checkpoint does not hold, included); an override that no generation played never
  # leaves config.ini and the checkpoint disagreeing
  "$duel" run --config "$cfg" --out "$tmp/ref" --generations 3 --quiet
  sed -n 2p "$tmp/ref/config.ini" | grep -q "^; checksum [0-9a-f]\{16\}: written by the run" || fail "no seal"
  sed -n 3p "$tmp/ref/config.ini" | grep -q "^; generations = 3, strength_every = 0$" || fail "the seal's keys"
  for edit in 's/^generations = 3/generations = 5/|generations = 5.*run wrote .generations = 3' \
              's/^strength_every = .*/strength_every = 1/|strength_every = 1.*run wrote .strength_every = 0'; do
    rm -rf "$tmp/h"
    cp -r "$tmp/ref" "$tmp/h"
    sed -i "${edit%%|*}" "$tmp/h/config.ini"
    expect_bad "h/config.ini says '${edit#*|}': a hand edit of config.ini is not taken" resume "$tmp/h" --generations 6
    cmp -s "$tmp/h/checkpoint.bin" "$tmp/ref/checkpoint.bin" || fail "a refused resume played ($edit)"
  done
  # the same change given the right way is taken (as for the parameters the checkpoint holds)
  "$duel" resume "$tmp/h" --generations 6 --set strength_every=1 --quiet || fail "the same change as --set"
  # an override on a finished run applies to no generation: refused, config.ini untouched
  cp -r "$tmp/ref" "$tmp/f"
  expect_bad "the run has played its 3 generations: an override (--set) applies to generations to come" \
    resume "$tmp/f" --set add_node_prob=0.05
  cmp -s "$tmp/f/config.ini" "$tmp/ref/config.ini" || fail "a refused override reached config.ini"
  # a resume with an override killed before its first checkpoint: config.ini says the override from generation 3
  # on ([overrides]), the checkpoint is at 3: they agree, and the next resume plays it (the same bytes as the resume
  # that was not killed)
  cp -r "$tmp/ref" "$tmp/k"
  "$duel" resume "$tmp/k" --set add_node_prob=0.05 --generations 4 --quiet
  cp -r "$tmp/k" "$tmp/full"
  for f in checkpoint.bin generations.csv dominance.csv; do cp "$tmp/ref/$f" "$tmp/k/$f"; done
  rm -f "$tmp/k/champions/gen-00003."*
  grep -qx "from 3 = add_node_prob=0.05" "$tmp/k/config.ini" || fail "the override's generation: $(tail -2 "$tmp/k/config.ini")"
  grep -q "^add_node_prob = 0.01$" "$tmp/k/config.ini" || fail "[neat] is not generation 0's"
  "$duel" resume "$tmp/k" --quiet || fail "a resume after an override that was never saved"
  cmp -s "$tmp/k/checkpoint.bin" "$tmp/full/checkpoint.bin" || fail "the scheduled override was not played"
  cp -r "$tmp/ref" "$tmp/plain"
  "$duel" resume "$tmp/plain" --generations 4 --quiet
  ! cmp -s "$tmp/k/checkpoint.bin" "$tmp/plain/checkpoint.bin" || fail "the override changed nothing: nothing tested"
  # §3: the override is in the checkpoint with its generation, and run --config RUN/config.ini plays the run again
  "$duel" run --config "$tmp/full/config.ini" --out "$tmp/again" --quiet
  for f in checkpoint.bin dominance.csv champions/gen-00003.blob; do
    cmp -s "$tmp/full/$f" "$tmp/again/$f" || fail "run --config RUN/config.ini: $f differs"
  done
  grep -q "generation 3: overrides from here on: add_node_prob=0.05" "$tmp/again/log.txt" || fail "not logged"
  grep -a -q "OVR1" "$tmp/full/checkpoint.bin" || fail "the checkpoint does not record the override"
  ! grep -a -q "OVR1" "$tmp/plain/checkpoint.bin" || fail "a run without overrides records some"
  # the same for a run against fixed opponents (its checkpoint a population's)
  presets=$(cd "$(dirname "$0")/../../configs" && pwd)
  "$duel" run --config "$presets/vs-forager-hunter.ini" --set pop_size=16 --generations 2 --out "$tmp/fx" --quiet
  "$duel" resume "$tmp/fx" --generations 4 --set add_node_prob=0.2 --quiet
  "$duel" run --config "$tmp/fx/config.ini" --out "$tmp/fy" --quiet
  cmp -s "$tmp/fx/checkpoint.bin" "$tmp/fy/checkpoint.bin" || fail "a fixed-opponent run's overrides were not played again"
  # an edit of a line the run has played is refused, naming the cause
  cp -r "$tmp/full" "$tmp/m"
  sed -i 's/^from 3 = /from 2 = /' "$tmp/m/config.ini"
  expect_bad "m/checkpoint.bin: the run was played with other \[overrides\] before generation 4 than config.ini says" \
    resume "$tmp/m" --generations 5
  cp -r "$tmp/full" "$tmp/m2"
  sed -i 's/^from 3 = add_node_prob=0.05/from 3 = add_node_prob=0.06/' "$tmp/m2/config.ini"
  expect_bad "m2/config.ini says 'add_node_prob = 0.06' but the run in its checkpoint has 'add_node_prob = 0.05'" \
    resume "$tmp/m2" --generations 5
  # what [overrides] refuses
  printf '[overrides]\nfrom 0 = add_node_prob=0.05\n' > "$tmp/o0.ini"
  expect_bad "o0.ini:2: \[overrides\] 'from 0': expected 'from G' with G a generation from 1 on" config --config "$tmp/o0.ini" --dump
  printf '[overrides]\nfrom 2 = seed=4\n' > "$tmp/o1.ini"
  expect_bad "o1.ini:2: \[overrides\] from 2: 'seed=4': expected key=value of a \[neat\] or \[coevolution\] parameter" \
    config --config "$tmp/o1.ini" --dump
  printf '[overrides]\nfrom 2 = pop_size=40\n' > "$tmp/o2.ini"
  expect_bad "\[overrides\] from 2: pop_size cannot change during a run" run --config "$cfg" --config "$tmp/o2.ini" --out "$tmp/never"
  # nor can the network step: the run's champions, dominants and strength rows are blobs of one step
  printf '[overrides]\nfrom 2 = net_step=propagate\n' > "$tmp/o3.ini"
  expect_bad "\[overrides\] from 2: net_step cannot change during a run" run --config "$cfg" --config "$tmp/o3.ini" --out "$tmp/never"
  cp -r "$tmp/ref" "$tmp/ns"
  before=$(snapshot "$tmp/ns")
  expect_bad "--set net_step: a run's network step cannot change; start a new run instead" \
    resume "$tmp/ns" --generations 6 --set net_step=propagate
  [ "$(snapshot "$tmp/ns")" = "$before" ] || fail "a refused net_step override changed the run"
  # a run directory from before the seal resumes as before
  cp -r "$tmp/ref" "$tmp/old"
  sed -i 2,3d "$tmp/old/config.ini"
  "$duel" resume "$tmp/old" --generations 4 --quiet || fail "a config.ini without a seal"
  cmp -s "$tmp/old/checkpoint.bin" "$tmp/plain/checkpoint.bin" || fail "an unsealed run went on differently"
  ;;
provenance)
  # §1: a champion copied out of its run keeps its world and step (genome file format 2); every result names them
  fixture=$(cd "$(dirname "$0")/fixtures/experiment-tiny" && pwd)
  "$duel" run --config "$cfg" --out "$tmp/p" --generations 3 --set net_step=propagate --set world.food_range=300 --quiet
  "$duel" run --config "$cfg" --out "$tmp/p2" --generations 3 --seed 8 --set net_step=propagate \
    --set world.food_range=300 --quiet
  "$duel" run --config "$cfg" --out "$tmp/v1" --generations 2 --quiet
  id=$("$duel" play "$tmp/p/champions/gen-00002.genome" builtin:idle --json | sed 's/.*"world_id":"\([0-9a-f]*\)".*/\1/')
  [ "${#id}" -eq 16 ] && [ "$id" != "$("$duel" play builtin:idle builtin:idle --json | sed 's/.*"world_id":"\([0-9a-f]*\)".*/\1/')" ] ||
    fail "the run's world: '$id'"
  cp "$tmp/p/champions/gen-00002.genome" "$tmp/out.genome"
  cp "$tmp/p/champions/gen-00002.blob" "$tmp/out.blob"
  # the genome file records its step and world: played out of the run as in it
  "$duel" play "$tmp/p/champions/gen-00002.genome" builtin:forager-hunter --games 288 --json > "$tmp/in.json"
  "$duel" play "$tmp/out.genome" builtin:forager-hunter --games 288 --json > "$tmp/out.json"
  grep -q "\"world_id\":\"$id\",\"world_from\":\"champions\",\"step\":{\"a\":\"propagate\",\"b\":\"builtin\"}" \
    "$tmp/out.json" || fail "the copied genome: $(cat "$tmp/out.json")"
  [ "$(sed 's/"a":"[^"]*",//' "$tmp/in.json")" = "$(sed 's/"a":"[^"]*",//' "$tmp/out.json")" ] ||
    fail "copied out, the champion plays otherwise: $(cat "$tmp/in.json" "$tmp/out.json")"
  "$duel" play "$tmp/out.genome" builtin:idle | grep -q "^world custom (identity $id); network step: A propagate, B builtin$" ||
    fail "play's text does not name the world and step: $("$duel" play "$tmp/out.genome" builtin:idle | tail -1)"
  # its firmware blob is a propagate one (format 2), and the export says the world
  "$duel" export "$tmp/out.genome" --c-array champ > "$tmp/champ.c"
  grep -q "format version 2" "$tmp/champ.c" && grep -q "Evolved in world custom $id (identity $id)" "$tmp/champ.c" ||
    fail "export of the copied genome: $(head -7 "$tmp/champ.c")"
  # render plays it in its own world and step too, and says so
  "$duel" render "$tmp/out.genome" builtin:idle --out "$tmp/frames" --every 300 > "$tmp/render.txt"
  grep -qx "world custom (identity $id); network step: west propagate, east builtin" "$tmp/render.txt" ||
    fail "render: $(cat "$tmp/render.txt")"
  # a blob records its step, not its world: play says plainly what it does
  "$duel" play "$tmp/out.blob" builtin:idle --json | grep -q '"world":"v1",.*"world_from":"default","step":{"west":"propagate"' ||
    fail "a blob out of its run: $("$duel" play "$tmp/out.blob" builtin:idle --json)"
  "$duel" play "$tmp/out.blob" builtin:idle 2> "$tmp/note" | grep -q "^world v1 (identity [0-9a-f]*); network step: A propagate, B builtin$" ||
    fail "play's text for a blob out of its run"
  grep -qx "duel_evolve: play: note: A (.*out.blob) records no world (a blob never does; its run's genome file does): played in world v1, the default (--world chooses another)" "$tmp/note" ||
    fail "no note for a blob out of its run: $(cat "$tmp/note")"
  # a genome file of format 1 (no origin) out of any run: sync, and said so
  python3 - "$tmp/out.genome" "$tmp/old.genome" <<'PY'
import struct, sys, zlib
b = open(sys.argv[1], "rb").read()
assert b[8] == 2
tag = struct.unpack_from("<I", b, 24)[0]
body = b[:8] + struct.pack("<I", 1) + b[12:20] + b[28 + tag:-4]
open(sys.argv[2], "wb").write(body + struct.pack("<I", zlib.crc32(body) & 0xFFFFFFFF))
PY
  "$duel" play "$tmp/old.genome" builtin:idle --json | grep -q '"world_from":"default","step":{"west":"sync"' ||
    fail "a format-1 genome file: $("$duel" play "$tmp/old.genome" builtin:idle --json)"
  # champions of two worlds are not played in one without --world; with it, a note says so
  expect_bad "out.genome is of world custom $id, .*gen-00001.genome of world v1: give --world" \
    play "$tmp/out.genome" "$tmp/v1/champions/gen-00001.genome"
  "$duel" play "$tmp/out.genome" "$tmp/v1/champions/gen-00001.genome" --world v1 > /dev/null 2> "$tmp/note" ||
    fail "--world v1"
  grep -q "note: A (.*out.genome) was made in world custom $id; played in world v1 as --world asks" "$tmp/note" ||
    fail "no note: $(cat "$tmp/note")"
  # an opponent made in another world plays in the run's, and the run says so (stderr and log.txt)
  printf '[opponents]\nplay = %s\n' "$tmp/out.genome" > "$tmp/o.ini"
  "$duel" run --config "$cfg" --config "$tmp/o.ini" --generations 1 --set pop_size=8 --out "$tmp/fo" --quiet 2> "$tmp/fo.err" ||
    fail "a run against an opponent of another world: $(cat "$tmp/fo.err")"
  grep -q "note: \[opponents\] .*out.genome was made in world custom $id; this run plays it in its own world, v1" "$tmp/fo.err" ||
    fail "no note: $(cat "$tmp/fo.err")"
  grep -q "run: \[opponents\] .*out.genome was made in world custom $id; played in the run's world, v1" "$tmp/fo/log.txt" ||
    fail "not logged"
  # --trace names the world and each side's step in every row; its LCM log records them, so log dump equals it
  "$duel" play "$tmp/out.genome" builtin:idle --food 7 --trace "$tmp/t.csv" --lcm-log "$tmp/t.lcm" > /dev/null
  head -1 "$tmp/t.csv" | grep -q ",food_mask,event,world_id,west_step,east_step$" || fail "trace header: $(head -1 "$tmp/t.csv")"
  [ "$(tail -n +2 "$tmp/t.csv" | grep -cv ",$id,propagate,builtin$")" -eq 0 ] || fail "trace rows: $(sed -n 2p "$tmp/t.csv")"
  "$duel" log dump "$tmp/t.lcm" | cmp - "$tmp/t.csv" || fail "log dump differs from the trace"
  "$duel" log info "$tmp/t.lcm" | grep -qx "network step: west propagate, east builtin" || fail "log info: no step"
  "$duel" log info "$tmp/t.lcm" | grep -qx "world: custom $id (its rules in the log's world message)" || fail "log info: no world"
  "$duel" render "$tmp/t.lcm" --out "$tmp/frames-log" --every 300 > "$tmp/render-log.txt"
  grep -qx "world custom (identity $id); network step: west propagate, east builtin" "$tmp/render-log.txt" ||
    fail "render of the log: $(cat "$tmp/render-log.txt")"
  # the blob, out of any run, is played in v1 and says so in the trace too (east: --side east)
  "$duel" play "$tmp/out.blob" builtin:idle --food 7 --side east --trace "$tmp/t2.csv" 2> /dev/null > /dev/null
  v1id=$("$duel" play builtin:idle builtin:idle --json | sed 's/.*"world_id":"\([0-9a-f]*\)".*/\1/')
  sed -n 2p "$tmp/t2.csv" | grep -q ",$v1id,builtin,propagate$" || fail "blob trace: $(sed -n 2p "$tmp/t2.csv")"
  # a run's recorded champion games are played in its world and name both networks' step
  "$duel" run --config "$cfg" --out "$tmp/rg" --generations 2 --set net_step=propagate --set world.food_range=300 \
    --record-champion-games --quiet
  "$duel" log info "$tmp/rg/games/gen-00001-west.lcm" > "$tmp/rg.txt"
  grep -qx "world: custom $id (its rules in the log's world message)" "$tmp/rg.txt" &&
    grep -qx "network step: west propagate, east propagate" "$tmp/rg.txt" || fail "recorded game: $(cat "$tmp/rg.txt")"
  # a log from before the net messages: the trace says it does not know
  # (the first 6000 bytes of a game: its complete steps are dumped, and the command says the rest is missing)
  "$duel" log dump "$(dirname "$0")/../fuzz/corpus/lcm_log/game-start.lcm" > "$tmp/old.csv" 2> /dev/null || true
  sed -n 2p "$tmp/old.csv" | grep -q ",b43972def416b019,unknown,unknown$" || fail "an old log's steps: $(sed -n 2p "$tmp/old.csv")"
  # ladder and compare name the world and the step in every row
  "$duel" ladder "$tmp/p" --against idle --csv "$tmp/l.csv" > /dev/null
  head -1 "$tmp/l.csv" | grep -qx "level,generation,population,hidden,connections,idle_wins,idle_losses,total_wins,total_losses,world,step" ||
    fail "ladder.csv header: $(head -1 "$tmp/l.csv")"
  [ "$(tail -n +2 "$tmp/l.csv" | grep -cv ",custom $id,propagate$")" -eq 0 ] || fail "ladder.csv rows: $(cat "$tmp/l.csv")"
  "$duel" compare "$tmp/p" --against "$tmp/p2" --csv "$tmp/c.csv" --json "$tmp/c.json" > "$tmp/c.txt"
  head -1 "$tmp/c.csv" | grep -q ",wins,world,candidate_step,ranking_step$" || fail "compare.csv: $(head -1 "$tmp/c.csv")"
  tail -1 "$tmp/c.csv" | grep -q ",custom $id,propagate,propagate$" || fail "compare.csv row: $(tail -1 "$tmp/c.csv")"
  grep -q "\"world_id\": \"$id\"" "$tmp/c.json" && grep -q '"step": "propagate"' "$tmp/c.json" || fail "compare --json"
  grep -q "world custom $id$" "$tmp/c.txt" || fail "compare's text: $(head -1 "$tmp/c.txt")"
  # an experiment's report names them, and refuses runs of several worlds
  cp -r "$fixture" "$tmp/x"
  "$duel" experiment report "$tmp/x" > /dev/null 2>&1 || fail "report of the fixture"
  head -1 "$tmp/x/report/runs.csv" | grep -q ",world,step$" && grep -q ",v1,sync$" "$tmp/x/report/table1.csv" &&
    grep -q ",v1,sync$" "$tmp/x/report/ladder.csv" && grep -q "in world v1 (identity" "$tmp/x/report/table1.md" ||
    fail "the report does not name world and step"
  rm -r "$tmp/x/report"
  cp -r "$tmp/x" "$tmp/x2"
  # a run's world is its checkpoint's: one put there from a run of another world is refused before any file
  cp "$tmp/p/checkpoint.bin" "$tmp/x/runs/random-1/checkpoint.bin"
  expect_bad "experiment: .*: runs of several worlds: runs/[a-z0-9-]* is of world v1, runs/random-1 of world custom $id" \
    experiment report "$tmp/x"
  [ ! -e "$tmp/x/report" ] || fail "a report of several worlds was written"
  # its config.ini's [world] edited: the run is not the plan's
  printf '[world]\nfood_range = 300\n' >> "$tmp/x2/runs/random-1/config.ini"
  expect_bad "experiment: .*random-1/config.ini belongs to another plan" experiment report "$tmp/x2"
  [ ! -e "$tmp/x2/report" ] || fail "a report of several worlds was written"
  ;;
records)
  # §3: records edited or put in place of the run's own are detected against the checkpoint: a champion blob of a
  # dominant swapped for another, a dominance.csv row edited or one the checkpoint lacks; resume repairs them
  "$duel" run --config "$cfg" --out "$tmp/r" --generations 6 --quiet
  [ "$(tail -n +2 "$tmp/r/dominance.csv" | wc -l)" -ge 2 ] || fail "fewer than 2 dominance levels: nothing tested"
  "$duel" ladder "$tmp/r" --top --against idle > "$tmp/want.txt"
  cp -r "$tmp/r" "$tmp/keep"
  top=$(tail -1 "$tmp/r/dominance.csv" | cut -d, -f2) first=$(sed -n 2p "$tmp/r/dominance.csv" | cut -d, -f2)
  topb=$tmp/r/champions/gen-$(printf %05d "$top").blob
  cp "$tmp/r/champions/gen-$(printf %05d "$first").blob" "$topb"
  expect_bad "r/champions/gen-$(printf %05d "$top").blob is not the checkpoint's dominant of level [0-9]* (a file put in its place): resume the run" \
    ladder "$tmp/r" --top --against idle
  expect_bad "is not the checkpoint's dominant" compare "$tmp/r" --against "$tmp/keep"
  "$duel" resume "$tmp/r" --quiet || fail "resume"
  cmp -s "$topb" "$tmp/keep/champions/gen-$(printf %05d "$top").blob" || fail "resume did not write the blob again"
  grep -q "resume: champions/gen-$(printf %05d "$top").blob was not the dominant of level" "$tmp/r/log.txt" || fail "not logged"
  "$duel" ladder "$tmp/r" --top --against idle | cmp -s - "$tmp/want.txt" || fail "the ladder after the repair"
  # a row the checkpoint lacks (a run killed between its records and its checkpoint, or a row added by hand)
  last=$(tail -1 "$tmp/r/dominance.csv")
  n=$(($(wc -l < "$tmp/r/dominance.csv")))
  printf '%s,5,%s 1:0\n' "$n" "${last#*,*,}" >> "$tmp/r/dominance.csv"
  expect_bad "r/dominance.csv: $n levels, but the checkpoint has $((n - 1)): resume the run to repair it" \
    ladder "$tmp/r" --top --against idle
  "$duel" resume "$tmp/r" --quiet || fail "resume"
  cmp -s "$tmp/r/dominance.csv" "$tmp/keep/dominance.csv" || fail "dominance.csv not rebuilt"
  # strength.csv: each row names the champion it measured; a row from another run is measured again on resume,
  # and a file written before the column goes on without it
  "$duel" run --config "$cfg" --out "$tmp/s1" --generations 3 --set strength_every=1 --quiet
  "$duel" run --config "$cfg" --out "$tmp/s2" --generations 3 --seed 9 --set strength_every=1 --quiet
  head -1 "$tmp/s1/strength.csv" | grep -q ",forager-hunter_timeouts,champion$" || fail "strength.csv: no champion column"
  cp "$tmp/s1/strength.csv" "$tmp/strength.keep"
  sed -i "3s/.*/$(sed -n 3p "$tmp/s2/strength.csv")/" "$tmp/s1/strength.csv"
  ! cmp -s "$tmp/s1/strength.csv" "$tmp/strength.keep" || fail "the two runs' rows are the same: nothing tested"
  "$duel" resume "$tmp/s1" --quiet || fail "resume"
  cmp -s "$tmp/s1/strength.csv" "$tmp/strength.keep" || fail "a transplanted strength row was kept"
  grep -q "resume: strength.csv: generation 1's row was not of the run's champion" "$tmp/s1/log.txt" || fail "not logged"
  sed -i 's/,[^,]*$//' "$tmp/s1/strength.csv"
  "$duel" resume "$tmp/s1" --generations 4 --quiet || fail "resume of an older strength.csv"
  [ "$(awk -F, '{print NF}' "$tmp/s1/strength.csv" | sort -u)" = 21 ] || fail "an older strength.csv mixed formats"
  # an edited row: another generation for a level
  sed -i "2s/^1,$first,/1,$((first + 1)),/" "$tmp/r/dominance.csv"
  cp "$tmp/r/champions/gen-$(printf %05d "$first").blob" "$tmp/r/champions/gen-$(printf %05d $((first + 1))).blob" 2>/dev/null || true
  expect_bad "r/dominance.csv: level 1 says generation $((first + 1)) .*, but the checkpoint's is generation $first" \
    ladder "$tmp/r" --against idle
  ;;
*)
  fail "unknown check $what"
  ;;
esac
echo "ok: $what"
