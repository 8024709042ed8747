# cli_lib.sh - what the command-line tests share, sourced after setting $duel: fail, and expect_bad.

fail() { echo "FAIL: $*"; exit 1; }

expect_bad() { # expect_bad PATTERN ARGS...: "$duel" ARGS exits with status 2 and one line on stderr matching PATTERN
  local pattern=$1 rc=0 msg
  shift
  msg=$("$duel" "$@" 2>&1 >/dev/null) || rc=$?
  [ "$rc" -eq 2 ] || fail "$*: exit $rc, expected 2 ($msg)"
  [ "$(printf '%s\n' "$msg" | wc -l)" -eq 1 ] || fail "$*: more than one line: $msg"
  printf '%s\n' "$msg" | grep -q -- "$pattern" || fail "$*: got '$msg', expected '$pattern'"
}
