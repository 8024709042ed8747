#!/usr/bin/env bash
# make_blobs.sh DUEL_BENCH DUEL_EVOLVE CONFIG OUT - the firmware tests' champions: duel_bench's networks (net202a: hidden nodes, recurrent connections) and a champion evolved by a short coevolution (OUT/champion.blob).
set -euo pipefail
bench=$1 duel=$2 cfg=$3 out=$4
rm -rf "$out"
mkdir -p "$out"
"$bench" --write-blobs "$out"
"$duel" run --config "$cfg" --out "$out/coev" --generations 5 --quiet
cp "$out/coev/champions/gen-00004.blob" "$out/champion.blob"
