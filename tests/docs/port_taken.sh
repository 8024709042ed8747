#!/usr/bin/env bash
# port_taken.sh SOURCE BUILD DOC.md SETUP - DOC's command blocks (tests/docs/readme_commands.sh) while another process
# holds every port its LCM hub lines name: they must pass all the same (issue 42: a second suite on the machine, or
# anything else on that port, once made the hub exit and the test talk to a hub that was not its own).
set -euo pipefail
src=$1 build=$2 doc=$3 setup=$4
ports=$(sed -n 's/.*lcm\.lcm\.TCPService \([0-9][0-9]*\).*/\1/p' "$doc" | sort -u)
[ -n "$ports" ] || { echo "FAIL: $doc names no hub port"; exit 1; }
command -v python3 > /dev/null || { echo "no python3: skipped"; exit 77; }
# the holder listens on each port (as another suite's hub would) until this script ends; a port something else
# already holds (another copy of this very test, in a second suite) is taken already, which is the point
python3 -c '
import errno, socket, sys, time
held = []
for p in sys.argv[1:]:
    s = socket.socket()
    try:
        s.bind(("127.0.0.1", int(p)))
        s.listen()
        held.append(s)
    except OSError as e:
        if e.errno != errno.EADDRINUSE:
            raise
print("held", flush=True)
time.sleep(3600)' $ports > "$build/.port_holder.$$" 2>&1 &
holder=$!
trap 'kill $holder 2>/dev/null || true; rm -f "$build/.port_holder.$$"' EXIT
for _ in $(seq 100); do grep -q held "$build/.port_holder.$$" 2>/dev/null && break; sleep 0.05; done
grep -q held "$build/.port_holder.$$" || { echo "FAIL: could not hold ports $ports: $(cat "$build/.port_holder.$$")"; exit 1; }
echo "ports $(echo $ports) held by another process"
# shellcheck disable=SC2086
"$src/tests/docs/readme_commands.sh" "$src" "$build" "$doc" "$setup"
