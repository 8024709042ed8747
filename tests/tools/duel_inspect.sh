#!/usr/bin/env bash
# duel_inspect.sh - duel_evolve inspect and dot from the outside: counts against the blob's size, names, Graphviz edges, atomic -o, bad input (exit 2, one line).
set -euo pipefail
duel=$1
bench=$2
what=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=/dev/null
. "$(dirname "$0")/cli_lib.sh"

field() { # field FILE KEY: the first word after "KEY: "
  sed -n "s/^$2: \([0-9a-zx]*\).*/\1/p" "$1"
}

"$bench" --write-blobs "$tmp" || fail "duel_bench --write-blobs failed"

case "$what" in
inspect)
  for net in net39a net202a net202b; do
    blob=$tmp/$net.blob
    "$duel" inspect "$blob" > "$tmp/$net.txt"
    out=$tmp/$net.txt
    size=$(wc -c < "$blob")
    conns=$(( (size - 32) / 4 ))
    [ "$(field "$out" size)" -eq "$size" ] || fail "$net: size line: $(grep '^size' "$out")"
    [ "$(field "$out" connections)" -eq "$conns" ] || fail "$net: $(grep '^connections:' "$out"), expected $conns"
    [ "$(grep -c '^conn ' "$out")" -eq "$conns" ] || fail "$net: connection lines != $conns"
    [ "$(field "$out" inputs)" -eq 13 ] && [ "$(field "$out" outputs)" -eq 3 ] || fail "$net: inputs/outputs"
    grep -q '^format version: 1$' "$out" || fail "$net: format version"
    grep -q '^crc32: 0x[0-9a-f]\{8\}$' "$out" || fail "$net: crc32"
    grep -q '^ram: [1-9][0-9]* bytes' "$out" || fail "$net: ram"
    hidden=$(field "$out" hidden)
    [ "$(grep -c '^node ' "$out")" -eq $((16 + hidden)) ] || fail "$net: node lines != $((16 + hidden))"
    for name in bias food_ahead food_left food_back_left food_back_right food_right robot_ahead robot_left \
      robot_back_left robot_back_right robot_right energy_diff wall turn_left turn_right forward; do
      grep -q "^node  *[0-9]*  [a-z]*  *$name " "$out" || fail "$net: no node line for $name"
    done
    grep -q '^node   0  bias ' "$out" && grep -q '^node  13  output  turn_left ' "$out" || fail "$net: node order"
    # every weight is its raw Q3.12 value / 4096 to 4 decimals
    awk '/^conn / { w = $(NF - ($NF == "recurrent" ? 3 : 2)); r = $(NF - ($NF == "recurrent" ? 1 : 0));
                    if (sprintf("%.4f", r / 4096) != w) { print "bad weight: " $0; bad = 1 } }
         END { exit bad }' "$out" || fail "$net: weights"
    rec=$(field "$out" recurrent)
    [ "$(grep -c '  recurrent$' "$out" || true)" -eq "$rec" ] || fail "$net: recurrent flags != $rec"
  done
  [ "$(field "$tmp/net39a.txt" hidden)" -eq 0 ] && [ "$(field "$tmp/net39a.txt" recurrent)" -eq 0 ] ||
    fail "net39a: expected no hidden node and no recurrent connection"
  [ "$(field "$tmp/net202a.txt" hidden)" -gt 0 ] && [ "$(field "$tmp/net202a.txt" recurrent)" -gt 0 ] ||
    fail "net202a: expected hidden nodes and recurrent connections"
  ;;
dot)
  for net in net39a net202a; do
    blob=$tmp/$net.blob
    conns=$(( ($(wc -c < "$blob") - 32) / 4 ))
    rec=$("$duel" inspect "$blob" | sed -n 's/^recurrent: \([0-9]*\).*/\1/p')
    "$duel" dot "$blob" > "$tmp/$net.dot"
    edges=$(grep -cE '^  n[0-9]+ -> n[0-9]+ \[penwidth' "$tmp/$net.dot" || true)
    [ "$edges" -eq "$conns" ] || fail "$net: $edges edges, expected $conns"
    [ "$(grep -E '^  n[0-9]+ -> ' "$tmp/$net.dot" | grep -c 'style=dashed' || true)" -eq "$rec" ] ||
      fail "$net: dashed edges != $rec recurrent"
    # the legend (the graph's label) and every hidden node in one rank=same row of its depth
    grep -q 'label=<<TABLE' "$tmp/$net.dot" && grep -q 'positive weight' "$tmp/$net.dot" &&
      grep -q 'dead hidden node' "$tmp/$net.dot" || fail "$net: no legend"
    hidden=$("$duel" inspect "$blob" | sed -n 's/^hidden: \([0-9]*\)$/\1/p')
    in_rows=$(awk '/^  subgraph depth[0-9]+_[0-9]+ \{$/ { on = 1; next } on && /^  \}$/ { on = 0 }
                   on && /rank=same/ { rows++ } on && /shape=circle/ { n++ } END { print n + 0 }' "$tmp/$net.dot")
    [ "$in_rows" -eq "$hidden" ] || fail "$net: $in_rows hidden nodes in depth rows, expected $hidden"
    # --min-weight W: exactly the connections of |raw| >= W * 4096 (inspect's raw Q3.12 weights)
    for w in 0.5 1 1.25; do
      want=$("$duel" inspect "$blob" | awk -v w="$w" '/^conn / { r = $(NF - 0); for (i = 1; i <= NF; i++) if ($i == "raw") r = $(i + 1);
             if (r < 0) r = -r; if (r >= w * 4096) n++ } END { print n + 0 }')
      got=$("$duel" dot "$blob" --min-weight "$w" | grep -cE '^  n[0-9]+ -> n[0-9]+ \[penwidth' || true)
      [ "$got" -eq "$want" ] || fail "$net: --min-weight $w drew $got edges, expected $want"
      "$duel" dot "$blob" --min-weight "$w" > "$tmp/w.dot"
      grep -qF "$want drawn, those of |w| &lt; $w left out" "$tmp/w.dot" ||
        fail "$net: --min-weight $w: no count in the title"
    done
    grep -q 'rank=source' "$tmp/$net.dot" && grep -q 'label="wall"' "$tmp/$net.dot" &&
      grep -q 'label="forward"' "$tmp/$net.dot" || fail "$net: ranks or labels missing"
    # -o writes the same bytes, through a temporary file that does not stay
    mkdir -p "$tmp/out"
    "$duel" dot -o "$tmp/out/$net.dot" "$blob" --min-weight 1 # an earlier output of dot: replaced
    "$duel" dot -o "$tmp/out/$net.dot" "$blob"
    cmp -s "$tmp/$net.dot" "$tmp/out/$net.dot" || fail "$net: -o output differs from stdout"
    if command -v dot > /dev/null; then
      dot -Tsvg "$tmp/$net.dot" > "$tmp/$net.svg" || fail "$net: dot -Tsvg failed"
      [ "$(grep -c 'class="edge"' "$tmp/$net.svg")" -eq "$conns" ] || fail "$net: svg edges != $conns"
    else
      echo "graphviz dot not installed: skipping the dot -Tsvg check"
    fi
  done
  [ "$(grep -c 'style=dashed' "$tmp/net202a.dot")" -gt 0 ] || fail "net202a: no dashed edge"
  [ "$(ls "$tmp/out")" = "$(printf 'net202a.dot\nnet39a.dot')" ] || fail "left over: $(ls "$tmp/out")"
  # a bad blob leaves an existing output alone
  printf 'not a blob' > "$tmp/bad.blob"
  expect_bad "bad.blob: not a valid champion blob" dot "$tmp/bad.blob" -o "$tmp/out/net39a.dot"
  cmp -s "$tmp/net39a.dot" "$tmp/out/net39a.dot" || fail "a failed dot -o changed the output"
  ;;
generic)
  # 4 inputs (in3 unused), 1 output (node 4), 1 hidden (node 5) with a self loop
  command -v gzip > /dev/null || { echo "gzip not installed: skipping (it computes the CRC)"; echo "ok: $what"; exit 0; }
  head28='NRTB\x01\x00\x20\x00\x04\x00\x01\x00\x01\x00\x05\x00\x34\x00\x00\x00\x0c\x00\x00\x00\x00\x00\x00\x00'
  conns='\x00\x04\x00\x10\x02\x04\x00\xf8\x05\x04\x00\x20\x01\x05\x00\x08\x05\x05\x00\xf0'
  printf "$head28$conns" > "$tmp/crc_input"
  { printf "$head28"; gzip -c < "$tmp/crc_input" | tail -c 8 | head -c 4; printf "$conns"; } > "$tmp/g.blob"
  "$duel" inspect "$tmp/g.blob" > "$tmp/g.txt"
  grep -q '^names: generic' "$tmp/g.txt" || fail "generic: $(cat "$tmp/g.txt")"
  grep -q '^node   0  bias    bias ' "$tmp/g.txt" && grep -q '^node   3  input   in3  .* out   0$' "$tmp/g.txt" &&
    grep -q '^node   4  output  out0 ' "$tmp/g.txt" && grep -q '^node   5  hidden  h5 ' "$tmp/g.txt" ||
    fail "generic: node lines: $(grep '^node' "$tmp/g.txt")"
  grep -q '^recurrent: 1 ' "$tmp/g.txt" || fail "generic: $(grep '^recurrent' "$tmp/g.txt")"
  grep -q '^conn    4  h5  *-> h5  *weight -1.0000  raw  -4096  recurrent$' "$tmp/g.txt" ||
    fail "generic: self loop: $(grep '^conn    4' "$tmp/g.txt")"
  grep -q '^conn    1  in2  *-> out0  *weight -0.5000  raw  -2048$' "$tmp/g.txt" || fail "generic: conn 1"
  "$duel" dot "$tmp/g.blob" > "$tmp/g.dot"
  grep -q 'n3 \[label="in3", shape=box, color=gray70' "$tmp/g.dot" || fail "generic: unused input not faded"
  grep -q 'n5 -> n5 .*style=dashed' "$tmp/g.dot" || fail "generic: self loop not dashed"
  grep -q 'n5 \[label="h5", shape=circle, width=0.3, fixedsize=false\];' "$tmp/g.dot" || fail "generic: h5 is not dead"
  grep -q '1 hidden (0 dead)' "$tmp/g.dot" || fail "generic: dead count"
  # in1 -> h5 made h5 -> h5: no input reaches h5 any more, so it is dead (grey dashed, its edges grey)
  conns='\x00\x04\x00\x10\x02\x04\x00\xf8\x05\x04\x00\x20\x05\x05\x00\x08\x05\x05\x00\xf0'
  printf "$head28$conns" > "$tmp/crc_input"
  { printf "$head28"; gzip -c < "$tmp/crc_input" | tail -c 8 | head -c 4; printf "$conns"; } > "$tmp/d.blob"
  "$duel" dot "$tmp/d.blob" > "$tmp/d.dot"
  grep -q 'n5 \[label="h5", shape=circle, width=0.3, fixedsize=false, style=dashed, color=gray60' "$tmp/d.dot" ||
    fail "dead: h5 not marked"
  grep -q '1 hidden (1 dead)' "$tmp/d.dot" || fail "dead: count"
  grep -q 'n5 -> n4 \[penwidth=1.12, color=gray60' "$tmp/d.dot" || fail "dead: its edge not grey"
  grep -q 'n0 -> n4 \[penwidth=0.81, color=black' "$tmp/d.dot" || fail "dead: a live edge greyed"
  ;;
bad-input)
  for cmd in inspect dot; do
    expect_bad "missing.blob: cannot open" $cmd "$tmp/missing.blob"
    printf 'NRTB this is not a blob at all, just text long enough' > "$tmp/text.blob"
    expect_bad "text.blob: not a valid champion blob: unknown blob format version" $cmd "$tmp/text.blob"
    printf 'hello' > "$tmp/short.blob"
    expect_bad "short.blob: not a valid champion blob: blob truncated" $cmd "$tmp/short.blob"
    head -c 100 "$tmp/net39a.blob" > "$tmp/cut.blob"
    expect_bad "cut.blob: not a valid champion blob: blob truncated" $cmd "$tmp/cut.blob"
    cp "$tmp/net39a.blob" "$tmp/flip.blob"
    printf '\x7f' | dd of="$tmp/flip.blob" bs=1 seek=50 conv=notrunc 2> /dev/null
    expect_bad "flip.blob: not a valid champion blob: checksum mismatch" $cmd "$tmp/flip.blob"
    expect_bad "usage: duel_evolve $cmd BLOB" $cmd
    expect_bad "usage: duel_evolve $cmd BLOB" $cmd "$tmp/net39a.blob" "$tmp/net39b.blob"
  done
  expect_bad "usage: duel_evolve inspect BLOB" inspect --what
  expect_bad "dot: -o needs a file name" dot "$tmp/net39a.blob" -o
  expect_bad "dot: --min-weight needs a value" dot "$tmp/net39a.blob" --min-weight
  expect_bad "dot: --min-weight takes a number from 0 to 8, not '9'" dot "$tmp/net39a.blob" --min-weight 9
  expect_bad "dot: --min-weight takes a number from 0 to 8, not 'nan'" dot "$tmp/net39a.blob" --min-weight nan
  expect_bad "nodir/x.dot: cannot write" dot "$tmp/net39a.blob" -o "$tmp/nodir/x.dot"
  ;;
*)
  echo "unknown check $what"; exit 2 ;;
esac
echo "ok: $what"
