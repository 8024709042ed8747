# lcm_hub.sh - sourced: LCM's Java TCP hub on a free loopback port, known to be this hub's and listening
# (lcm_hub_start JAVA JAR LOG_PREFIX sets $lcm_hub_port and $lcm_hub_pid, or returns 1 with the hub's last
# message in $lcm_hub_error). Used by tests/lcm/lcm_cli.sh and tests/docs/readme_commands.sh. Never a fixed port: another suite on the machine, or anything else on a port,
# makes a hub exit ("Address already in use") with status 0, and a test must not then talk to a hub that is not
# its own (issue 42).

# 1 when process PID has a socket listening on loopback TCP port PORT (read from /proc: no ss or netstat needed).
lcm_hub_listens() {
  local pid=$1 port=$2 hex inode
  hex=$(printf '%04X' "$port")
  # /proc/net/tcp(6): local address hex IP:PORT, state 0A (LISTEN), the socket's inode in column 10
  for inode in $(awk -v p=":$hex" '$2 ~ p"$" && $4 == "0A" { print $10 }' /proc/net/tcp /proc/net/tcp6 2>/dev/null); do
    if ls -l "/proc/$pid/fd" 2>/dev/null | grep -q "socket:\[$inode\]"; then return 0; fi
  done
  return 1
}

lcm_hub_start() { # lcm_hub_start JAVA JAR LOG_PREFIX [FIRST_PORT]: FIRST_PORT tried first (a test of a taken port)
  local java=$1 jar=$2 log=$3 first=${4:-} try port i
  lcm_hub_error=
  for try in 1 2 3 4 5 6 7 8; do
    port=$(( 20000 + (RANDOM * 32768 + RANDOM + $$ + try) % 40000 ))
    [ "$try" -gt 1 ] || [ -z "$first" ] || port=$first
    "$java" -cp "$jar" lcm.lcm.TCPService "$port" > "$log-$port.log" 2>&1 &
    lcm_hub_pid=$!
    for i in $(seq 200); do
      # the Java process itself (its children share the socket) holds the listening socket: ours, not another's
      if lcm_hub_listens "$lcm_hub_pid" "$port"; then lcm_hub_port=$port; return 0; fi
      kill -0 "$lcm_hub_pid" 2>/dev/null || break # it exited (the port taken): another port
      sleep 0.05
    done
    lcm_hub_error=$(tail -2 "$log-$port.log" 2>/dev/null | tr '\n' ' ')
    kill "$lcm_hub_pid" 2>/dev/null || true
    wait "$lcm_hub_pid" 2>/dev/null || true
  done
  return 1
}
