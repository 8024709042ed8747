#!/usr/bin/env bash
# The whole test suite: unit tests (normal, Release and ASan+UBSan builds), every decoder's fuzzer,
# the Cortex-M0+ cross build of the runtime with its sizes, the firmware figures under QEMU, and a
# short benchmark smoke run.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
./scripts/deps.sh

echo "== build and unit tests (RelWithDebInfo)"
# with the Python package (python/), built against the test environment deps.sh made
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNEAT_TOOLS=ON -DNEAT_PYTHON=ON \
      -DPython_EXECUTABLE="${NEAT_PY_VENV:-$HOME/.local/lib/neat-duel/venv}/bin/python" >/dev/null
ninja -C build
ctest --test-dir build --output-on-failure -j "$jobs"

echo "== unit tests under AddressSanitizer + UndefinedBehaviorSanitizer (-O1)"
# -O1 rather than -O0: the sanitized suite runs in half the time (807 s -> 396 s on 2 cores), and -O0
# keeps its own check in both builds (ctest duelsim/test_golden_O0_*: duelsim and the runtime at -O0).
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_FLAGS_DEBUG="-g -O1" \
      -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" -DNEAT_SANITIZE=ON -DNEAT_TOOLS=ON >/dev/null
ninja -C build-asan
ctest --test-dir build-asan --output-on-failure -j "$jobs"

echo "== Release build (-O3 for every library, as a packager builds it): warnings as errors, the core unit tests"
cmake -S . -B build-release -G Ninja -DCMAKE_BUILD_TYPE=Release -DNEAT_TOOLS=ON >/dev/null
ninja -C build-release
ctest --test-dir build-release --output-on-failure -j "$jobs" -R '^(libneat|runtime|duelsim)/'

echo "== identical duel traces from the Release, -O3, -O2 and -O1 sanitizer builds"
cmake -S . -B build-o2 -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNEAT_DUELSIM_O3=OFF -DNEAT_TESTS=OFF >/dev/null
ninja -C build-o2 duel_evolve
mkdir -p build/nets
./build/bin/duel_bench --write-blobs build/nets
for game in "builtin:forager-hunter builtin:forager --food 0" "builtin:forager builtin:forager-hunter --food 77 --side east" \
            "builtin:hunter builtin:forager-hunter" "build/nets/net39a.blob build/nets/net39b.blob --food 5" \
            "build/nets/net202a.blob builtin:forager-hunter --food 140 --side east" \
            "build/nets/net202b.blob build/nets/net39a.blob"; do
  # shellcheck disable=SC2086
  ./build/bin/duel_evolve play $game --trace build/trace-o3.csv > /dev/null
  # shellcheck disable=SC2086
  ./build-o2/bin/duel_evolve play $game --trace build/trace-o2.csv > /dev/null
  # shellcheck disable=SC2086
  ./build-asan/bin/duel_evolve play $game --trace build/trace-o1.csv > /dev/null
  # shellcheck disable=SC2086
  ./build-release/bin/duel_evolve play $game --trace build/trace-release.csv > /dev/null
  cmp build/trace-o3.csv build/trace-release.csv
  cmp build/trace-o3.csv build/trace-o2.csv
  cmp build/trace-o3.csv build/trace-o1.csv
done
echo "traces identical"

echo "== runtime and duelsim for Cortex-M0+ (arm-none-eabi-gcc -mcpu=cortex-m0plus -mthumb -Os)"
cmake -S . -B build-arm -G Ninja -DCMAKE_TOOLCHAIN_FILE=cmake/arm-none-eabi.cmake \
      -DCMAKE_BUILD_TYPE=MinSizeRel -DNEAT_RUNTIME_ONLY=ON >/dev/null
ninja -C build-arm
# Nothing but memcpy/memset from libc, and no floating-point helper.
undef=$(arm-none-eabi-nm -u build-arm/libnrt.a | awk '$1 == "U" {print $2}' | { grep -v '^nrt_' || true; } | sort -u | tr '\n' ' ')
echo "runtime needs from outside: $undef"
for s in $undef; do
  case "$s" in memcpy|memset) ;; *) echo "FAIL: the runtime needs $s"; exit 1;; esac
done

# duelsim: integer arithmetic only, so no floating-point helper may be linked.
if arm-none-eabi-nm -u build-arm/libduelsim.a | grep -E '__aeabi_[fd]|__(add|sub|mul|div)[sd]f3|__float|__fix'; then
  echo "FAIL: duelsim needs floating point on Cortex-M0+"; exit 1
fi
echo "duelsim links no floating-point helper"

echo "== firmware: the runtime on Cortex-M0+, RAM, instructions per step under QEMU (docs/firmware.md)"
# (the QEMU identity tests themselves are in ctest: examples/firmware/test)
./scripts/firmware_figures.sh build

echo "== fuzzing every decoder (libFuzzer, 30 s each, one per core; scripts/fuzz.sh SECONDS for a longer campaign)"
CC=clang cmake -S . -B build-fuzz -G Ninja -DNEAT_FUZZ=ON -DNEAT_TESTS=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
ninja -C build-fuzz fuzzers
./scripts/fuzz.sh 30 build-fuzz

echo "== benchmark smoke run"
./build/bin/neat_bench xor --runs 10 --quiet | tail -1
