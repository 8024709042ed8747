#!/usr/bin/env bash
# bench_cli.sh - neat_bench from the outside: bad configuration is refused with file:line, the
# dumped configuration loads back unchanged, the built-in defaults are bench/<task>.ini's, the results
# do not depend on the thread count, and every core means those of the process's affinity mask.
set -euo pipefail
bench=$1
what=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

case "$what" in
bad-config)
  printf '[neat]\npop_size = 10\npop_sise = 10\n' > "$tmp/typo.ini"
  set +e
  msg=$("$bench" xor --config "$tmp/typo.ini" 2>&1 >/dev/null); rc=$?
  set -e
  [ "$rc" -eq 2 ] || { echo "exit $rc, expected 2"; exit 1; }
  echo "$msg" | grep -q "typo.ini:3: unknown key 'pop_sise' (did you mean 'pop_size'?)" || { echo "got: $msg"; exit 1; }
  printf '[neat]\nc3 = -1\n' > "$tmp/range.ini"
  set +e
  msg=$("$bench" xor --config "$tmp/range.ini" 2>&1 >/dev/null); rc=$?
  set -e
  [ "$rc" -eq 2 ] && echo "$msg" | grep -q "range.ini:2: bad value '-1' for c3" || { echo "got $rc: $msg"; exit 1; }
  printf '[nope]\nx = 1\n' > "$tmp/section.ini"
  set +e
  msg=$("$bench" xor --config "$tmp/section.ini" 2>&1 >/dev/null); rc=$?
  set -e
  [ "$rc" -eq 2 ] && echo "$msg" | grep -q "section.ini:2: unknown section \[nope\]" || { echo "got $rc: $msg"; exit 1; }
  ;;
dump-roundtrip)
  for task in xor pole pole-nv; do
    "$bench" "$task" --dump-config > "$tmp/a.ini"
    "$bench" "$task" --config "$tmp/a.ini" --dump-config > "$tmp/b.ini"
    cmp "$tmp/a.ini" "$tmp/b.ini"
  done
  ;;
built-in)
  # (bench_cli.sh NEAT_BENCH built-in BENCH_SOURCE_DIR) from a directory with nothing else in it: the
  # compiled-in defaults give exactly what the source tree's files give
  src=$3
  cp "$bench" "$tmp/neat_bench"
  for task in xor pole pole-nv; do
    (cd "$tmp" && ./neat_bench "$task" --dump-config > "$tmp/built-in.ini")
    "$bench" "$task" --config "$src/$task.ini" --dump-config > "$tmp/file.ini"
    cmp "$tmp/built-in.ini" "$tmp/file.ini" || { echo "$task: built-in defaults differ from $src/$task.ini"; exit 1; }
  done
  ;;
affinity)
  # a thread count of 0 means the cores this process may use (taskset, a job's cpuset), not the machine's
  command -v taskset > /dev/null || { echo "taskset not installed: skipped"; exit 77; }
  want=$(taskset -c 0 nproc)
  got=$(taskset -c 0 "$bench" xor --runs 4 --threads 0 --quiet | tail -1 | sed -n 's/.*"threads":\([0-9]*\).*/\1/p')
  [ "$got" = "$want" ] || { echo "on core 0 alone: $got threads, expected $want"; exit 1; }
  ;;
threads)
  one=$("$bench" xor --runs 12 --threads 1 --quiet | tail -1 | sed 's/,"threads".*//')
  two=$("$bench" xor --runs 12 --threads 2 --quiet | tail -1 | sed 's/,"threads".*//')
  [ "$one" = "$two" ] || { echo "1 thread:  $one"; echo "2 threads: $two"; exit 1; }
  echo "$one" | grep -q '"failures":0' || { echo "unexpected failures: $one"; exit 1; }
  ;;
profile)
  # [neat] profile = neat-cpp-1.2.1 sets NEAT C++ 1.2.1's switches before every other key, wherever it stands,
  # so a key of the file overrides it (the key before it as much as the one after); the dump loads back
  printf '[neat]\nadd_conn_rule = any\nprofile = neat-cpp-1.2.1\nrecur_only_prob = 0.5\n' > "$tmp/p.ini"
  "$bench" xor --config "$tmp/p.ini" --dump-config > "$tmp/p.dump"
  for want in "profile = neat-cpp-1.2.1" "add_conn_rule = any" "recur_only_prob = 0.5" "equal_fitness_rule = smaller" \
              "reenable_rule = neat-cpp" "species_rep = champion" "weight_mut_rule = neat-cpp" \
              "elitism_rule = offspring" "interspecies_rule = neat-cpp" "identical_rule = equal" \
              "offspring_rounding = skim" "speciate_rule = interleaved" "stagnation_rule = neat-cpp" \
              "dropoff_age = 1000" "pop_stagnation_rule = delta-coding" "pop_stagnation = 0"; do
    grep -qx "$want" "$tmp/p.dump" || { echo "missing '$want' in:"; cat "$tmp/p.dump"; exit 1; }
  done
  "$bench" xor --config "$tmp/p.dump" --dump-config > "$tmp/p2.dump"
  cmp "$tmp/p.dump" "$tmp/p2.dump"
  # the values the profile does not set stay the file's and the defaults'
  grep -qx "pop_size = 256" "$tmp/p.dump" && grep -qx "add_node_prob = 0.01" "$tmp/p.dump" || { echo "pop_size changed by the profile"; exit 1; }
  # a configuration without the release's rules dumps as before they existed: net_step is its last key
  "$bench" xor --dump-config | tail -1 | grep -qx "net_step = sync" || { echo "the default dump changed"; exit 1; }
  ! "$bench" xor --dump-config | grep -q "^profile\|^equal_fitness_rule\|^pop_stagnation_rule\|^cull_" || { echo "release keys in a default dump"; exit 1; }
  printf '[neat]\ncull_age = 21\n' > "$tmp/one.ini"
  "$bench" xor --config "$tmp/one.ini" --dump-config | grep -qx "cull_age = 21" || { echo "a lone switch not dumped"; exit 1; }
  printf '[neat]\nprofile = neat-cpp\n' > "$tmp/bad.ini"
  set +e
  msg=$("$bench" xor --config "$tmp/bad.ini" 2>&1 >/dev/null); rc=$?
  set -e
  [ "$rc" -eq 2 ] && echo "$msg" | grep -q "bad.ini:2: bad value 'neat-cpp' for profile: expected one of default, neat-cpp-1.2.1" ||
    { echo "got $rc: $msg"; exit 1; }
  ;;
*)
  echo "unknown check $what"; exit 2 ;;
esac
echo "ok: $what"
