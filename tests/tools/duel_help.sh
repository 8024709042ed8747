#!/usr/bin/env bash
# duel_help.sh - every duel_evolve command answers --help and -h on stdout with exit 0, describing every option its synopsis in `duel_evolve --help` names; an option given last without its value is "needs a value" only when the command takes it.
set -euo pipefail
duel=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=/dev/null
. "$(dirname "$0")/cli_lib.sh"

"$duel" --help > "$tmp/usage" || fail "duel_evolve --help: exit $?"
commands=$(sed -n 's/^ *\(usage: \)\{0,1\}duel_evolve \([a-z][a-z-]*\).*/\2/p' "$tmp/usage" | sort -u)
[ "$(echo "$commands" | wc -w)" -ge 14 ] || fail "only these commands in the usage: $commands"
for c in $commands; do
  for h in --help -h; do
    rc=0
    "$duel" "$c" $h > "$tmp/out" 2> "$tmp/err" || rc=$?
    [ "$rc" -eq 0 ] || fail "$c $h: exit $rc ($(cat "$tmp/err"))"
    [ ! -s "$tmp/err" ] || fail "$c $h wrote to stderr: $(cat "$tmp/err")"
    grep -q "^usage: duel_evolve $c" "$tmp/out" || fail "$c $h: no usage line"
  done
  # every option of the command's synopsis lines, described on a line of its own
  for opt in $(grep -E "^ *(usage: )?duel_evolve $c( |$)" "$tmp/usage" | grep -oE -- '(^| |\[|\()--?[a-z][a-z-]*' |
               sed 's/^[ [(]*//' | sort -u); do
    grep -qE -- "^  $opt( |$)" "$tmp/out" || fail "$c --help does not describe $opt"
  done
  # --help anywhere among the arguments, after others
  "$duel" "$c" something --help > /dev/null || fail "$c something --help: exit $?"
done
# options given last
expect_bad "render: unknown option '--bogus'" render builtin:idle builtin:idle --out "$tmp/r" --bogus
expect_bad "play: --food needs a value" play builtin:idle builtin:idle --food
expect_bad "play: unknown option '--nope'" play builtin:idle builtin:idle --nope
expect_bad "node world: unknown option '--nope'" node world --nope
expect_bad "node controller: --lcm needs a value" node controller x.blob --lcm
expect_bad "run: --config needs a value" run --config
expect_bad "resume: --set needs a value" resume "$tmp" --set
expect_bad "config: --set needs a value" config --dump --set
echo "ok: $(echo "$commands" | wc -w) commands"
