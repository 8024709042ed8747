#!/usr/bin/env bash
# render_cli.sh - duel_evolve render and render-net from the outside: frame files, same bytes twice, LCM logs drawn as the game, the MP4 through ffmpeg, the network picture through dot, bad input (exit 2, one line, nothing left behind).
set -euo pipefail
duel=$1
bench=$2
what=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=/dev/null
. "$(dirname "$0")/../tools/cli_lib.sh"
unset DISPLAY WAYLAND_DISPLAY # off-screen: no display at all

png_size() { # png_size FILE: "WIDTH HEIGHT" from the IHDR chunk, after checking the signature
  [ "$(od -An -tx1 -N8 "$1" | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "$1: not a PNG"
  od -An -tu1 -j16 -N8 "$1" | awk '{ print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4, $5 * 16777216 + $6 * 65536 + $7 * 256 + $8 }'
}

# the game: forager-hunter (west) catches idle (east) after T steps
steps=$("$duel" play builtin:forager-hunter builtin:idle | sed -n 's/.* after \([0-9]*\) steps/\1/p')
[ -n "$steps" ] || fail "play gave no step count"
game=(builtin:forager-hunter builtin:idle --food training --side west)

case "$what" in
frames)
  # frames 0, 25, 50, ... and the final state: ceil(T / 25) + 1 files, all 200 x 200
  "$duel" render "${game[@]}" --out "$tmp/f" --size 200 --every 25 > "$tmp/out.txt"
  want=$(( (steps + 24) / 25 + 1 ))
  [ "$(find "$tmp/f" -type f | wc -l)" -eq "$want" ] || fail "$(find "$tmp/f" -type f | wc -l) files, expected $want"
  for k in $(seq 0 $((want - 1))); do
    f=$(printf '%s/f/frame-%05d.png' "$tmp" "$k")
    [ "$(png_size "$f")" = "200 200" ] || fail "$f: size $(png_size "$f")"
  done
  grep -q "west wins (collision, more energy) after $steps steps" "$tmp/out.txt" || fail "outcome line: $(cat "$tmp/out.txt")"
  grep -Eq "^$want frames in [0-9.]+ s \([0-9.]+ frames/s" "$tmp/out.txt" || fail "no frame rate line"
  # consecutive frames differ (the robots move), the side swap moves the colours
  cmp -s "$tmp/f/frame-00000.png" "$tmp/f/frame-00001.png" && fail "frames 0 and 1 are identical"
  "$duel" render builtin:idle builtin:forager-hunter --side east --out "$tmp/g" --size 200 --every 25 > /dev/null
  cmp -s "$tmp/f/frame-00003.png" "$tmp/g/frame-00003.png" || fail "A east against B west: not the same game"
  ;;
deterministic)
  # the same command twice: the same bytes, file by file; --sensors draws more
  "$duel" render "${game[@]}" --out "$tmp/a" --size 160 --every 40 --sensors > /dev/null
  "$duel" render "${game[@]}" --out "$tmp/b" --size 160 --every 40 --sensors > /dev/null
  n=0
  for f in "$tmp"/a/*.png; do
    cmp "$f" "$tmp/b/$(basename "$f")" || fail "$(basename "$f") differs between two runs"
    n=$((n + 1))
  done
  [ "$n" -ge 2 ] || fail "only $n frames"
  "$duel" render "${game[@]}" --out "$tmp/c" --size 160 --every 40 > /dev/null
  cmp -s "$tmp/a/frame-00001.png" "$tmp/c/frame-00001.png" && fail "--sensors changed nothing"
  # --trails: other pixels on a later frame, the first frame (no path yet) the same; deterministic too
  "$duel" render "${game[@]}" --out "$tmp/t" --size 160 --every 40 --trails > /dev/null
  "$duel" render "${game[@]}" --out "$tmp/t2" --size 160 --every 40 --trails > /dev/null
  cmp -s "$tmp/c/frame-00000.png" "$tmp/t/frame-00000.png" || fail "--trails changed frame 0"
  cmp -s "$tmp/c/frame-00001.png" "$tmp/t/frame-00001.png" && fail "--trails changed nothing"
  cmp "$tmp/t/frame-00001.png" "$tmp/t2/frame-00001.png" || fail "--trails: two runs differ"
  [ -z "$(find "$tmp" -name '*.tmp')" ] || fail "temporary files left: $(find "$tmp" -name '*.tmp')"
  ;;
video)
  command -v ffmpeg > /dev/null || { echo "ffmpeg not installed: skipped"; exit 77; }
  "$duel" render "${game[@]}" --out "$tmp/v" --size 128 --every 20 --video "$tmp/game.mp4" --fps 10 > "$tmp/out.txt"
  n=$(find "$tmp/v" -name 'frame-*.png' | wc -l)
  [ -s "$tmp/game.mp4" ] || fail "no video"
  grep -q "^video: $tmp/game.mp4 ($n frames at 10 frames/s)" "$tmp/out.txt" || fail "video line: $(cat "$tmp/out.txt")"
  [ "$(od -An -c -j4 -N4 "$tmp/game.mp4" | tr -d ' ')" = ftyp ] || fail "not an MP4 (no ftyp box)"
  if command -v ffprobe > /dev/null; then
    got=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames,codec_name,width,height \
          -of csv=p=0 "$tmp/game.mp4")
    [ "$got" = "h264,128,128,$n" ] || fail "ffprobe: '$got', expected h264,128,128,$n"
  fi
  [ -z "$(find "$tmp" -name '*.tmp')" ] || fail "temporary files left"
  # more frames in the directory than this game's (a longer game before): the video has this game's only
  "$duel" render builtin:idle builtin:idle --out "$tmp/long" --size 64 --every 250 > /dev/null
  "$duel" render "${game[@]}" --out "$tmp/long" --size 64 --every 200 --video "$tmp/short.mp4" > /dev/null
  if command -v ffprobe > /dev/null; then
    got=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$tmp/short.mp4")
    [ "$got" -eq $(( (steps + 199) / 200 + 1 )) ] || fail "short video: $got frames"
  fi
  ;;
video-kill)
  # kill -9 of render --video while ffmpeg encodes: ffmpeg dies with it (it was left running), and the next
  # render of the same video takes over the temporary file the killed one left
  command -v ffmpeg > /dev/null || { echo "ffmpeg not installed: skipped"; exit 77; }
  "$duel" render builtin:idle builtin:spinner --out "$tmp/k" --size 600 --every 1 --video "$tmp/k.mp4" > /dev/null &
  rpid=$!
  ff=""
  for _ in $(seq 3000); do
    ff=$(pgrep -P "$rpid" ffmpeg || true)
    [ -n "$ff" ] && break
    kill -0 "$rpid" 2>/dev/null || break
    sleep 0.02
  done
  [ -n "$ff" ] || fail "ffmpeg never started under render --video"
  kill -9 "$rpid"
  wait "$rpid" 2>/dev/null || true
  # alive: the process exists and is no zombie (an orphan nobody reaps yet is dead all the same)
  alive() { [ -r "/proc/$1/stat" ] && [ "$(sed 's/.*) \(.\).*/\1/' "/proc/$1/stat" 2>/dev/null)" != Z ]; }
  for _ in $(seq 100); do alive "$ff" || break; sleep 0.02; done
  if alive "$ff"; then kill -9 "$ff"; fail "ffmpeg $ff outlived the killed render"; fi
  [ ! -e "$tmp/k.mp4" ] || fail "a killed render left a video"
  "$duel" render "${game[@]}" --out "$tmp/k2" --size 64 --every 50 --video "$tmp/k.mp4" > /dev/null
  [ -s "$tmp/k.mp4" ] || fail "no video after the kill"
  [ -z "$(find "$tmp" -name '*.tmp')" ] || fail "temporary files left: $(find "$tmp" -name '*.tmp')"
  ;;
lcm)
  # a game recorded as an LCM log draws the same frames, byte for byte, as the game played here
  "$duel" play "${game[@]}" --lcm-log "$tmp/game.lcm" > /dev/null
  "$duel" render "$tmp/game.lcm" --out "$tmp/log" --size 128 --every 30 > "$tmp/out.txt"
  "$duel" render "${game[@]}" --out "$tmp/live" --size 128 --every 30 > /dev/null
  grep -q "west wins (collision, more energy) after $steps steps" "$tmp/out.txt" || fail "log outcome: $(cat "$tmp/out.txt")"
  n=0
  for f in "$tmp"/live/*.png; do
    cmp "$f" "$tmp/log/$(basename "$f")" || fail "$(basename "$f"): the log's frame differs from the game's"
    n=$((n + 1))
  done
  [ "$n" -eq $(( (steps + 29) / 30 + 1 )) ] && [ "$(find "$tmp/log" -type f | wc -l)" -eq "$n" ] || fail "$n frames"
  # a truncated log and a file that is not a log: exit 2, one line, no directory made
  head -c 3000 "$tmp/game.lcm" > "$tmp/cut.lcm"
  expect_bad "cut.lcm: .*truncated" render "$tmp/cut.lcm" --out "$tmp/cut"
  printf 'this is not an LCM event log\n' > "$tmp/notlcm.lcm"
  expect_bad "notlcm.lcm: .*not an LCM event log" render "$tmp/notlcm.lcm" --out "$tmp/cut"
  [ ! -e "$tmp/cut" ] || fail "a bad log left $tmp/cut"
  ;;
render-net)
  command -v dot > /dev/null || { echo "graphviz not installed: skipped"; exit 77; }
  "$bench" --write-blobs "$tmp" > /dev/null
  echo old > "$tmp/net.png"
  expect_bad "net.png exists and is not a picture from duel_evolve render-net: refusing to replace it" \
    render-net "$tmp/net202a.blob" --out "$tmp/net.png"
  [ "$(cat "$tmp/net.png")" = old ] || fail "render-net replaced a file that is not its picture"
  "$duel" render-net "$tmp/net202a.blob" --out "$tmp/net.png" --force
  "$duel" render-net "$tmp/net202a.blob" --out "$tmp/net.png" # its own picture: replaced
  read -r w h < <(png_size "$tmp/net.png")
  [ "$w" -gt 200 ] && [ "$h" -gt 200 ] || fail "net.png is $w x $h"
  # the same picture as dot -Tpng on the dot command's output
  "$duel" dot "$tmp/net202a.blob" | dot -Tpng > "$tmp/direct.png"
  "$duel" render-net "$tmp/net202a.blob" --out "$tmp/net2.png"
  [ "$(png_size "$tmp/direct.png")" = "$(png_size "$tmp/net2.png")" ] || fail "not the dot command's picture"
  # at most about 2000 pixels wide for a 202-connection network (size="20,14" at 96 dpi)
  [ "$w" -le 1920 ] && [ "$h" -le 1344 ] || fail "net.png is $w x $h, more than 1920 x 1344"
  "$duel" render-net "$tmp/net202a.blob" --min-weight 1 --out "$tmp/net3.png"
  "$duel" dot "$tmp/net202a.blob" --min-weight 1 | dot -Tpng > "$tmp/direct3.png"
  [ "$(png_size "$tmp/direct3.png")" = "$(png_size "$tmp/net3.png")" ] || fail "--min-weight: not the dot command's picture"
  [ "$(png_size "$tmp/net3.png")" != "$(png_size "$tmp/net2.png")" ] || fail "--min-weight 1 changed nothing"
  [ -z "$(find "$tmp" -name '*.tmp')" ] || fail "temporary files left"
  ;;
bad-input)
  printf 'this is not an LCM event log\n' > "$tmp/notlcm.lcm"
  expect_bad "notlcm.lcm: .*not an LCM event log" render "$tmp/notlcm.lcm" --out "$tmp/x1"
  expect_bad "missing.lcm" render "$tmp/missing.lcm" --out "$tmp/x1"
  expect_bad "unknown builtin" render builtin:nope builtin:idle --out "$tmp/x1"
  [ ! -e "$tmp/x1" ] || fail "bad input left the --out directory"
  # --out under a regular file: cannot be created (root can write anywhere, so no chmod trick)
  : > "$tmp/file"
  expect_bad "file/frames: cannot create the directory" render "${game[@]}" --out "$tmp/file/frames"
  expect_bad "cannot write in the directory" render "${game[@]}" --out /proc
  # no ffmpeg on PATH: said before anything is drawn
  mkdir "$tmp/empty"
  rc=0
  msg=$(PATH=$tmp/empty "$duel" render "${game[@]}" --out "$tmp/nofm" --video "$tmp/v.mp4" 2>&1 >/dev/null) || rc=$?
  [ "$rc" -eq 2 ] || fail "no ffmpeg: exit $rc"
  [ "$(printf '%s\n' "$msg" | wc -l)" -eq 1 ] && printf '%s\n' "$msg" | grep -q "needs ffmpeg" || fail "no ffmpeg: '$msg'"
  [ ! -e "$tmp/nofm" ] && [ ! -e "$tmp/v.mp4" ] || fail "no ffmpeg: something was written"
  expect_bad "v.mp4: cannot write" render "${game[@]}" --out "$tmp/x2" --video "$tmp/nodir/v.mp4"
  expect_bad "size takes an integer from 64 to 2048" render "${game[@]}" --out "$tmp/x3" --size 10
  expect_bad "every takes an integer" render "${game[@]}" --out "$tmp/x3" --every 0
  expect_bad "food takes an integer from 0 to 143" render "${game[@]}" --food 144 --out "$tmp/x3"
  expect_bad "side takes west or east" render builtin:idle builtin:idle --side up --out "$tmp/x3"
  expect_bad "not one in a log" render "$tmp/notlcm.lcm" --food 3 --out "$tmp/x3"
  expect_bad "unknown builtin" render builtin:nope builtin:idle --out "$tmp/x3"
  expect_bad "unknown option" render builtin:idle builtin:idle --out "$tmp/x3" --colour red
  expect_bad "usage" render builtin:idle builtin:idle
  expect_bad "unexpected argument" render a b c --out "$tmp/x3"
  [ ! -e "$tmp/x3" ] || [ -z "$(ls -A "$tmp/x3")" ] || fail "bad arguments left files"
  # render-net
  "$bench" --write-blobs "$tmp" > /dev/null
  rc=0
  msg=$(PATH=$tmp/empty "$duel" render-net "$tmp/net39a.blob" --out "$tmp/n.png" 2>&1 >/dev/null) || rc=$?
  [ "$rc" -eq 2 ] && [ "$(printf '%s\n' "$msg" | wc -l)" -eq 1 ] && printf '%s\n' "$msg" | grep -q "needs Graphviz dot" ||
    fail "render-net without dot: exit $rc, '$msg'"
  printf 'NRTB not a blob, just some text to read' > "$tmp/bad.blob"
  expect_bad "bad.blob: not a valid champion blob" render-net "$tmp/bad.blob" --out "$tmp/n.png"
  expect_bad "n.png: cannot write" render-net "$tmp/net39a.blob" --out "$tmp/nodir/n.png"
  expect_bad "usage" render-net "$tmp/net39a.blob"
  expect_bad "min-weight takes a number from 0 to 8" render-net "$tmp/net39a.blob" --min-weight -1 --out "$tmp/n.png"
  expect_bad "min-weight takes a number from 0 to 8" render-net "$tmp/net39a.blob" --min-weight x --out "$tmp/n.png"
  [ ! -e "$tmp/n.png" ] || fail "render-net left n.png"
  [ -z "$(find "$tmp" -name '*.tmp')" ] || fail "temporary files left"
  ;;
*)
  fail "unknown check $what"
  ;;
esac
echo "ok: $what"
