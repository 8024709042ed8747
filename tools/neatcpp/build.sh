#!/bin/sh
# build.sh - builds neatcpp_bench (docs/neat-cpp.md) against a checkout of the NEAT C++ 1.2.1 release.
# usage: tools/neatcpp/build.sh CHECKOUT [BUILD_DIR]   (BUILD_DIR default: build-neatcpp, in the current directory)
# The release's sources are compiled from CHECKOUT as they are; nothing of it is copied into this tree. The build is
# neatcpp_bench (libneat, the runtime, the benchmark evaluators) and, with the tools, neatcpp_duel; no tests.
set -eu
if [ $# -lt 1 ] || [ $# -gt 2 ]; then
    echo "usage: $0 CHECKOUT [BUILD_DIR]" >&2
    echo "  CHECKOUT: a checkout of the NEAT C++ 1.2.1 release, e.g." >&2
    echo "    git clone https://github.com/andnovar/NEAT neat-cpp-1.2.1" >&2
    exit 2
fi
src=$(cd "$(dirname "$0")/../.." && pwd)
[ -d "$1" ] || { echo "$0: $1: no such directory (a checkout of the NEAT C++ release)" >&2; exit 2; }
checkout=$(cd "$1" && pwd)
build=${2:-build-neatcpp}
missing=""
for f in src/population.cpp include/genome.h params256.ne; do
    [ -f "$checkout/$f" ] || missing="$missing $f"
done
if [ -n "$missing" ]; then
    echo "$0: $checkout does not look like the NEAT C++ 1.2.1 release: no$missing" >&2
    if [ -f "$checkout/HEAD" ] && [ -d "$checkout/objects" ]; then
        echo "  (it looks like a bare git repository: clone it first, git clone $checkout DIR)" >&2
    fi
    exit 2
fi
gen=""
command -v ninja >/dev/null 2>&1 && gen="-G Ninja"
# shellcheck disable=SC2086 # $gen is one option or none
# the tools too (AUTO: when their packages are there, as scripts/deps.sh installs them): neatcpp_duel is duel_evolve
cmake -S "$src" -B "$build" $gen -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNEAT_CPP_DIR="$checkout" \
    -DNEAT_TOOLS=AUTO -DNEAT_TESTS=OFF -DNEAT_INSTALL=OFF
cmake --build "$build" --target neatcpp_bench -j "${NEAT_JOBS:-1}"
echo "built $build/bin/neatcpp_bench (release at $checkout)"
if cmake --build "$build" --target help | grep -q neatcpp_duel; then
    cmake --build "$build" --target neatcpp_duel -j "${NEAT_JOBS:-1}"
    echo "built $build/bin/neatcpp_duel"
else
    echo "no neatcpp_duel: the tools' packages are missing (scripts/deps.sh)"
fi
