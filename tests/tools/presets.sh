#!/usr/bin/env bash
# presets.sh - the baselines of configs/ through the command line: generation 0's sizes, fixed and simplifying runs never adding structure, the best-topology start from a blob or a genome file, random fitness.
set -euo pipefail
duel=$1
configs=$2
what=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=/dev/null
. "$(dirname "$0")/cli_lib.sh"
# small and quick, otherwise the preset as it is
small=(--set pop_size=16 --set compare_configs=4 --set species_opponents=2 --set hof_opponents=2
       --set first_opponents=2 --quiet)

col() { # col CSV NAME: the column's values, one per line
  awk -F, -v name="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i; next } { print $c }' "$1"
}
# sizes RUN GENS HIDDEN CONNS: every population of every generation has exactly these sizes
exact_sizes() {
  local f=$1/generations.csv
  [ "$(tail -n +2 "$f" | wc -l)" -eq $((2 * $2)) ] || fail "$f: not $2 generations"
  for c in min_hidden max_hidden; do
    [ "$(col "$f" $c | sort -u)" = "$3" ] || fail "$f: $c $(col "$f" $c | sort -u | tr '\n' ' '), expected $3"
  done
  for c in min_connections max_connections; do
    [ "$(col "$f" $c | sort -u)" = "$4" ] || fail "$f: $c $(col "$f" $c | sort -u | tr '\n' ' '), expected $4"
  done
}
gen0() { # gen0 RUN HIDDEN CONNS: generation 0's populations all of these sizes
  local f=$1/generations.csv
  [ "$(awk -F, 'NR > 1 && $1 == 0' "$f" | wc -l)" -eq 2 ] || fail "$f: no generation 0"
  for c in min_hidden max_hidden; do
    [ "$(col "$f" $c | head -2 | sort -u)" = "$2" ] || fail "$f: generation 0 $c is not $2"
  done
  for c in min_connections max_connections; do
    [ "$(col "$f" $c | head -2 | sort -u)" = "$3" ] || fail "$f: generation 0 $c is not $3"
  done
}

case "$what" in
fixed)
  # the paper's counts: 10^2 + 16*10 + 3 = 263 and 5^2 + 16*5 + 39 = 144, never changed
  "$duel" run --config "$configs/fixed-10.ini" "${small[@]}" --generations 6 --out "$tmp/f10"
  exact_sizes "$tmp/f10" 6 10 263
  "$duel" run --config "$configs/fixed-5.ini" "${small[@]}" --generations 6 --out "$tmp/f5"
  exact_sizes "$tmp/f5" 6 5 144
  grep -q "start hidden:5:inputs (5 hidden nodes, 144 connections)" "$tmp/f5/log.txt" || fail "log: $(cat "$tmp/f5/log.txt")"
  grep -q "^start = hidden:5:inputs$" "$tmp/f5/config.ini" || fail "config.ini does not record the start"
  "$duel" inspect "$tmp/f5" | grep -q "population A: 16 genomes .* hidden 5..5, connections 144..144; innovations in use 0..143, next 144" ||
    fail "inspect: $("$duel" inspect "$tmp/f5")"
  # the same start through --set on the paper's configuration
  "$duel" run --config "$configs/paper.ini" --set mode=fixed --set start=hidden:5:inputs "${small[@]}" --generations 6 \
    --out "$tmp/f5b"
  cmp "$tmp/f5/checkpoint.bin" "$tmp/f5b/checkpoint.bin" || fail "fixed-5.ini is not paper.ini with mode and start"
  ;;
simplify)
  # 12^2 + 16*12 + 3 = 339 at the start, then only fewer: no innovation is ever created
  "$duel" run --config "$configs/simplifying.ini" "${small[@]}" --generations 15 --out "$tmp/s"
  gen0 "$tmp/s" 12 339
  for c in max_connections max_hidden; do
    max=$(col "$tmp/s/generations.csv" $c | sort -n | tail -1)
    [ "$max" -le "$([ $c = max_hidden ] && echo 12 || echo 339)" ] || fail "simplify grew: $c $max"
  done
  min=$(col "$tmp/s/generations.csv" min_connections | sort -n | head -1)
  [ "$min" -lt 339 ] || fail "simplify removed nothing in 15 generations"
  "$duel" inspect "$tmp/s" | grep -c "innovations in use 0\.\.338, next 339$" | grep -qx 2 ||
    fail "an innovation was created: $("$duel" inspect "$tmp/s")"
  ;;
best)
  # the topology of a champion blob: kept, weights drawn afresh
  "$duel" run --config "$configs/paper.ini" "${small[@]}" --set add_node_prob=0.3 --set add_conn_prob=0.5 \
    --generations 8 --out "$tmp/c"
  blob=$(ls "$tmp/c/champions/"*.blob | tail -1)
  h=$("$duel" inspect "$blob" | sed -n 's/^hidden: //p')
  n=$("$duel" inspect "$blob" | sed -n 's/^connections: //p')
  [ "$h" -gt 0 ] || fail "the champion has no hidden node to keep"
  expect_bad "start = blob needs the champion's path" run --config "$configs/best-topology.ini" --out "$tmp/b0"
  "$duel" run --config "$configs/best-topology.ini" --set "start=blob:$blob" "${small[@]}" --generations 4 \
    --out "$tmp/b"
  exact_sizes "$tmp/b" 4 "$h" "$n"
  grep -q "^start = blob:$blob$" "$tmp/b/config.ini" || fail "config.ini does not record the blob"
  # weights re-drawn: no individual of generation 0 is the champion itself
  ! cmp -s "$blob" "$tmp/b/champions/gen-00000.blob" || fail "generation 0 kept the blob's weights"
  # resume: the start cannot change, and the checkpoint carries it when the blob is gone
  "$duel" resume "$tmp/b" --generations 5 --quiet
  expect_bad "start topology cannot change" resume "$tmp/b" --set start=minimal
  cp "$blob" "$tmp/moved.blob"
  "$duel" run --config "$configs/best-topology.ini" --set "start=blob:$tmp/moved.blob" "${small[@]}" \
    --generations 3 --out "$tmp/b2"
  rm "$tmp/moved.blob"
  "$duel" resume "$tmp/b2" --generations 4 --quiet
  exact_sizes "$tmp/b2" 4 "$h" "$n"
  # config.ini naming another start than the checkpoint's
  sed -i "s|^start = .*|start = hidden:3:bias|" "$tmp/b2/config.ini"
  expect_bad "checkpoint.bin: started from $h hidden nodes and $n connections, but config.ini says start = hidden:3:bias" \
    resume "$tmp/b2"
  expect_bad "nope.blob: cannot read the start blob" run --config "$configs/best-topology.ini" \
    --set start=blob:"$tmp/nope.blob" --out "$tmp/b3"
  printf 'not a blob' > "$tmp/bad.blob"
  expect_bad "bad.blob: not a valid champion blob" run --config "$configs/best-topology.ini" \
    --set start=blob:"$tmp/bad.blob" --out "$tmp/b4"
  [ ! -e "$tmp/b4" ] || fail "a refused run made its directory"
  ;;
genome)
  # a champion's genome file: every generation's champion is saved with its genes; inspect shows them and the
  # same network as the blob; play takes it; it seeds a run (its topology, innovations and disabled genes kept,
  # weights drawn afresh) that resumes without it; bad files are one line naming the file and the byte
  "$duel" run --config "$configs/paper.ini" "${small[@]}" --set add_node_prob=0.3 --set add_conn_prob=0.5 \
    --generations 8 --out "$tmp/c"
  [ "$(ls "$tmp/c/champions/"*.genome | wc -l)" -eq 8 ] || fail "not one genome file per generation"
  g=$tmp/c/champions/gen-00007.genome blob=$tmp/c/champions/gen-00007.blob
  "$duel" inspect "$g" > "$tmp/g.txt"
  genes=$(sed -n 's/^connection genes: \([0-9]*\) .*/\1/p' "$tmp/g.txt")
  [ "$(grep -c '^gene conn ' "$tmp/g.txt")" -eq "$genes" ] || fail "connection gene lines != $genes"
  [ "$(grep -c '^gene node ' "$tmp/g.txt")" -eq "$(sed -n 's/^node genes: \([0-9]*\) .*/\1/p' "$tmp/g.txt")" ] ||
    fail "node gene lines"
  grep -q '^genome inputs: 12 ' "$tmp/g.txt" && grep -q '^genome outputs: 3$' "$tmp/g.txt" || fail "genome shape"
  # after its genes, the network: exactly what inspect says of the blob (but the file name)
  diff <(sed -n '/^its network/,$p' "$tmp/g.txt" | tail -n +3) <("$duel" inspect "$blob" | tail -n +2) ||
    fail "the genome's network is not the blob's"
  # (the first line names the files)
  [ "$("$duel" play "$g" builtin:forager | tail -n +2)" = "$("$duel" play "$blob" builtin:forager | tail -n +2)" ] ||
    fail "play: the genome plays otherwise than its blob"
  h=$(sed -n 's/^hidden: //p' "$tmp/g.txt")
  n=$(sed -n 's/^connections: //p' "$tmp/g.txt")
  [ "$h" -gt 0 ] || fail "the champion has no hidden node to keep"
  cp "$g" "$tmp/seed.genome"
  "$duel" run --config "$configs/best-topology.ini" --set "start=genome:$tmp/seed.genome" "${small[@]}" \
    --generations 3 --out "$tmp/s"
  # generation 0 is the genome's network; its disabled genes may be enabled again by crossover later, but no
  # gene is added (mode = fixed)
  gen0 "$tmp/s" "$h" "$n"
  [ "$(col "$tmp/s/generations.csv" max_connections | sort -n | tail -1)" -le "$genes" ] || fail "a gene was added"
  [ "$(col "$tmp/s/generations.csv" max_hidden | sort -u)" = "$h" ] || fail "a node was added"
  # the genome's own innovation numbers, not 0, 1, ... as from a blob
  top=$(awk '/^gene conn / {print $3}' "$tmp/g.txt" | sort -n | tail -1)
  "$duel" inspect "$tmp/s" | grep -q "^start: .*, $n connections, innovations 0\.\.$top$" ||
    fail "the start's innovations: $("$duel" inspect "$tmp/s" | grep '^start:'), expected 0..$top"
  grep -q "^start = genome:$tmp/seed.genome$" "$tmp/s/config.ini" || fail "config.ini does not record the genome"
  ! cmp -s "$blob" "$tmp/s/champions/gen-00000.blob" || fail "generation 0 kept the genome's weights"
  rm "$tmp/seed.genome"
  "$duel" resume "$tmp/s" --generations 4 --quiet
  [ "$(tail -n +2 "$tmp/s/generations.csv" | wc -l)" -eq 8 ] || fail "resumed without the genome: not 4 generations"
  expect_bad "start topology cannot change" resume "$tmp/s" --set start=minimal
  # bad files: cut short, a flipped byte, a blob where a genome is named
  head -c 60 "$g" > "$tmp/cut.genome"
  expect_bad "cut.genome: not a valid genome file: .* at byte [0-9]*" inspect "$tmp/cut.genome"
  expect_bad "cut.genome: not a valid genome file: .* at byte [0-9]*" play "$tmp/cut.genome" builtin:idle
  expect_bad "cut.genome: not a valid genome file: .* at byte [0-9]*" run --config "$configs/best-topology.ini" \
    --set start=genome:"$tmp/cut.genome" --out "$tmp/s2"
  cp "$g" "$tmp/flip.genome"
  printf '\377' | dd of="$tmp/flip.genome" bs=1 seek=30 conv=notrunc status=none
  expect_bad "flip.genome: not a valid genome file: checksum mismatch at byte" inspect "$tmp/flip.genome"
  expect_bad "blob.genome: not a valid genome file: malformed file" run --config "$configs/best-topology.ini" \
    --set start=genome:"$(cp "$blob" "$tmp/blob.genome"; echo "$tmp/blob.genome")" --out "$tmp/s3"
  [ ! -e "$tmp/s2" ] && [ ! -e "$tmp/s3" ] || fail "a refused run made its directory"
  ;;
random)
  # every game a coin: no game is played, so thousands of games take no time; sizes drift both ways
  "$duel" run --config "$configs/random-fitness.ini" --set pop_size=32 --quiet --generations 30 --out "$tmp/r1"
  "$duel" run --config "$configs/random-fitness.ini" --set pop_size=32 --quiet --generations 30 --out "$tmp/r2" \
    --threads 1
  cmp "$tmp/r1/checkpoint.bin" "$tmp/r2/checkpoint.bin" || fail "random fitness is not deterministic"
  grep -q "random fitness" "$tmp/r1/log.txt" || fail "the log does not say random fitness"
  mean=$(awk -F, 'NR > 1 { s += $4; n++ } END { printf "%.0f", 100 * s / n / 24 }' "$tmp/r1/generations.csv")
  [ "$mean" -ge 40 ] && [ "$mean" -le 60 ] || fail "mean wins $mean % of 24, not about half"
  last=$(tail -1 "$tmp/r1/generations.csv")
  [ "$(col "$tmp/r1/generations.csv" max_connections | tail -1)" -gt 39 ] || fail "no growth: $last"
  ;;
config)
  # reals in their shortest exact form, which reads back to the same configuration
  "$duel" config --dump --config "$configs/paper.ini" > "$tmp/paper.ini"
  grep -qx "delta_t_step = 0.3" "$tmp/paper.ini" || fail "config --dump: $(grep delta_t_step "$tmp/paper.ini")"
  ! grep -qE "= [0-9.]*[0-9]{15,}" "$tmp/paper.ini" || fail "long numbers: $(grep -E "= [0-9.]{15,}" "$tmp/paper.ini")"
  "$duel" config --dump --config "$tmp/paper.ini" --set weight_perturb_power=0.1 --set c3=0.30000000000000004 \
    > "$tmp/again.ini"
  grep -qx "weight_perturb_power = 0.1" "$tmp/again.ini" && grep -qx "c3 = 0.30000000000000004" "$tmp/again.ini" ||
    fail "shortest form: $(grep -E "^(c3|weight_perturb_power) " "$tmp/again.ini")"
  "$duel" config --dump --config "$tmp/again.ini" | cmp - "$tmp/again.ini" || fail "the dump does not read back"
  # the rule coevolution cannot use, and the start's syntax
  expect_bad "pop_stagnation must be 0 in coevolution" config --dump --set pop_stagnation=35
  expect_bad "hidden:H:inputs or hidden:H:bias with H in 1..240" config --dump --set start=hidden:0:bias
  expect_bad "expected minimal, hidden:H:inputs, hidden:H:bias, blob:PATH or genome:PATH" config --dump --set start=huge
  expect_bad "start = hidden:240: 256 nodes, more than max_nodes = 200" config --dump --set start=hidden:240:bias \
    --set max_nodes=200
  printf '[neat]\npop_stagnation = 35\n' > "$tmp/ps.ini"
  expect_bad "ps.ini: \[neat\] pop_stagnation must be 0" run --config "$tmp/ps.ini" --out "$tmp/ps"
  # a checkpoint of the format before start topologies were stored
  mkdir "$tmp/v1"
  "$duel" config --dump --config "$configs/quick.ini" > "$tmp/v1/config.ini"
  { printf 'NEATCOEV\001\000\000\000'; head -c 100 /dev/zero; } > "$tmp/v1/checkpoint.bin"
  expect_bad "checkpoint.bin: offset 8: checkpoint format 1, but this duel_evolve reads format 3" resume "$tmp/v1"
  expect_bad "checkpoint.bin: offset 8: checkpoint format 1, but this duel_evolve reads format 3" inspect "$tmp/v1"
  # every preset is paper.ini but for its documented keys
  for p in fixed-10:mode=fixed,start=hidden:10:bias fixed-5:mode=fixed,start=hidden:5:inputs \
           simplifying:mode=simplify,start=hidden:12:bias random-fitness:random_fitness=true \
           best-topology:mode=fixed,start=blob:x.blob; do
    name=${p%%:*}
    sets=()
    IFS=, read -ra kv <<< "${p#*:}"
    for s in "${kv[@]}"; do sets+=(--set "$s"); done
    # (best-topology's placeholder needs a path before it loads)
    diff <("$duel" config --dump --config "$configs/paper.ini" "${sets[@]}") \
         <("$duel" config --dump --config "$configs/$name.ini" "${sets[@]}") ||
      fail "$name.ini differs from paper.ini beyond ${p#*:}"
  done
  ;;
*)
  fail "unknown check $what"
  ;;
esac
