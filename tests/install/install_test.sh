#!/usr/bin/env bash
# install_test.sh - the libraries as a user gets them: installed into a prefix and found by find_package or
# pkg-config, shared with only the public API exported, or added with add_subdirectory (tests/CMakeLists.txt).
#   install_test.sh STEP SOURCE_DIR WORK_DIR C_COMPILER VERSION
# STEP: prefix-static | prefix-shared (configure, build, install the libraries alone into WORK_DIR/KIND/prefix),
# find-package-KIND, pkg-config-KIND (build examples/parity against that prefix and run it), symbols (the shared
# libraries' exports against the installed headers' declarations), subproject.
set -euo pipefail
step=$1 src=$2 work=$3 cc=$4 version=$5
gen=()
if command -v ninja > /dev/null; then gen=(-G Ninja); fi
fail() { echo "FAIL: $*" >&2; exit 1; }
# quiet configure and build: the output only when they fail
run_quiet() {
  local log
  log=$(mktemp)
  if ! "$@" > "$log" 2>&1; then cat "$log" >&2; rm -f "$log"; fail "$*"; fi
  rm -f "$log"
}
# parity's line, exit 0: it solved 3-bit parity
run_parity() {
  local out
  out=$("$@") || fail "$1 exited $?: $out"
  echo "$out"
  [[ $out == "3-bit parity solved in generation "* ]] || fail "$1: unexpected output: $out"
}

# the run engine's example: 10 generations of tests/tools/coev-small.ini into a fresh run directory, a line each
run_engine_check() {
  local out
  rm -rf "$2"
  out=$("$1" "$src/tests/tools/coev-small.ini" "$2") || fail "$1 exited $?: $out"
  [[ $(grep -c '^generation [0-9]* of 10: ' <<< "$out") == 10 && -f $2/checkpoint.bin && -f $2/dominance.csv ]] ||
    fail "$1: unexpected output or run directory: $out"
  echo "$out" | grep '^generation 10 of 10'
}

case $step in
prefix-static | prefix-shared)
  kind=${step#prefix-}
  shared=OFF
  [[ $kind == shared ]] && shared=ON
  rm -rf "$work/$kind"
  run_quiet cmake -S "$src" -B "$work/$kind/build" "${gen[@]}" -DCMAKE_C_COMPILER="$cc" -DCMAKE_BUILD_TYPE=Release \
    -DNEAT_TOOLS=OFF -DNEAT_TESTS=OFF -DBUILD_SHARED_LIBS=$shared
  run_quiet cmake --build "$work/$kind/build"
  run_quiet cmake --install "$work/$kind/build" --prefix "$work/$kind/prefix"
  p=$work/$kind/prefix
  libdir=$(cd "$p" && ls -d lib*/pkgconfig | head -1) || fail "no pkgconfig directory under $p"
  libdir=${libdir%/pkgconfig}
  for f in include/neat_duel/{neat.h,neat_coev.h,neat_phenotype.h,nrt.h,nrt_dense.h,duel.h,neat_duel_version.h} \
           include/neat_duel/{duel_engine.h,duel_config.h} "$libdir"/pkgconfig/{neat,nrt,duelsim,duelengine}.pc "$libdir"/cmake/neat_duel/neat_duel{Config,ConfigVersion,Targets}.cmake \
           share/doc/neat_duel/LICENSE; do
    [[ -f $p/$f ]] || fail "not installed: $f"
  done
  for l in neat nrt duelsim duelengine; do
    if [[ $kind == shared ]]; then
      so=$p/$libdir/lib$l.so
      [[ -f $so ]] || fail "no $so"
      soname=$(readelf -d "$so" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
      # 0.x: major.minor in the SONAME (cmake/neat_library.cmake)
      [[ $soname == "lib$l.so.${version%.*}" ]] || fail "$l: SONAME $soname, expected lib$l.so.${version%.*}"
      [[ -f $p/$libdir/lib$l.so.$version ]] || fail "no lib$l.so.$version"
    else
      [[ -f $p/$libdir/lib$l.a ]] || fail "no lib$l.a"
    fi
    v=$(PKG_CONFIG_PATH=$p/$libdir/pkgconfig pkg-config --modversion "$l")
    [[ $v == "$version" ]] || fail "$l.pc: Version $v, expected $version"
  done
  grep -q "set(PACKAGE_VERSION \"$version\")" "$p/$libdir/cmake/neat_duel/neat_duelConfigVersion.cmake" ||
    fail "neat_duelConfigVersion.cmake: not version $version"
  echo "$kind libraries installed in $p ($libdir)"
  ;;
find-package-static | find-package-shared)
  kind=${step#find-package-}
  for ex in parity coev_game; do
    rm -rf "$work/$kind/$ex"
    run_quiet cmake -S "$src/examples/$ex" -B "$work/$kind/$ex" "${gen[@]}" -DCMAKE_C_COMPILER="$cc" \
      -DCMAKE_PREFIX_PATH="$work/$kind/prefix"
    run_quiet cmake --build "$work/$kind/$ex"
  done
  run_parity "$work/$kind/parity/parity"
  "$work/$kind/coev_game/coev_game" | tail -1
  # the run engine's example (docs/library.md): a small coevolution into a run directory
  rm -rf "$work/$kind/run_engine"
  run_quiet cmake -S "$src/examples/run_engine" -B "$work/$kind/run_engine" "${gen[@]}" -DCMAKE_C_COMPILER="$cc" \
    -DCMAKE_PREFIX_PATH="$work/$kind/prefix"
  run_quiet cmake --build "$work/$kind/run_engine"
  run_engine_check "$work/$kind/run_engine/run_engine" "$work/$kind/run-fp"
  if [[ $kind == shared ]]; then
    # (ldd's output whole first: grep -q leaving early would break ldd's pipe, a failure under pipefail)
    libs=$(ldd "$work/$kind/parity/parity")
    [[ $libs == *"libneat.so.${version%.*} => $work/$kind/prefix/"* ]] ||
      fail "parity does not run on the installed libneat.so: $libs"
  fi
  ;;
pkg-config-static | pkg-config-shared)
  kind=${step#pkg-config-}
  p=$work/$kind/prefix
  pcdir=$(ls -d "$p"/lib*/pkgconfig | head -1)
  # a static libneat needs libm from the link line: --static adds the Libs.private; a shared one carries it
  static=()
  [[ $kind == static ]] && static=(--static)
  flags=$(PKG_CONFIG_PATH=$pcdir pkg-config "${static[@]}" --cflags --libs neat)
  echo "cc parity.c $flags"
  # shellcheck disable=SC2086
  "$cc" -std=c99 -o "$work/$kind/parity-pc" "$src/examples/parity/parity.c" $flags
  LD_LIBRARY_PATH=$(dirname "$pcdir") run_parity "$work/$kind/parity-pc"
  flags=$(PKG_CONFIG_PATH=$pcdir pkg-config "${static[@]}" --cflags --libs duelengine)
  echo "cc run_engine.c $flags"
  # shellcheck disable=SC2086
  "$cc" -std=c99 -o "$work/$kind/run_engine-pc" "$src/examples/run_engine/run_engine.c" $flags
  LD_LIBRARY_PATH=$(dirname "$pcdir") run_engine_check "$work/$kind/run_engine-pc" "$work/$kind/run-pc"
  ;;
symbols)
  p=$work/shared/prefix
  # every function the installed public headers declare (comments dropped first), not the static inline ones
  declared=$(cat "$p"/include/neat_duel/*.h | "$cc" -w -fpreprocessed -dD -E -P - |
             grep -v '^static inline' | grep -oE '\b(neat|nrt|duel)_[A-Za-z0-9_]+[[:space:]]*\(' | tr -d '( ' | sort -u)
  exported=$(for l in neat nrt duelsim duelengine; do nm -D --defined-only "$p"/lib*/lib$l.so; done | awk '{print $3}' | sort -u)
  extra=$(comm -13 <(echo "$declared") <(echo "$exported"))
  missing=$(comm -23 <(echo "$declared") <(echo "$exported"))
  [[ -z $extra ]] || fail "exported but not declared in a public header: $(echo $extra)"
  [[ -z $missing ]] || fail "declared in a public header but not exported: $(echo $missing)"
  # a function of libneat/src/neat_internal.h, for the record that the check sees what it should
  [[ $'\n'$exported$'\n' != *$'\n'neat_mutate$'\n'* ]] || fail "neat_mutate exported"
  echo "exported: exactly the $(echo "$exported" | wc -l) functions the public headers declare"
  ;;
subproject)
  # a parent project of its own: add_subdirectory(neat-duel), its libraries only, a program linked with neat
  d=$work/subproject
  rm -rf "$d"
  mkdir -p "$d/src"
  cat > "$d/src/CMakeLists.txt" << CMAKE
cmake_minimum_required(VERSION 3.18)
project(parent C)
set(CMAKE_BUILD_TYPE Debug)
add_subdirectory("$src" neat-duel)
add_executable(app "$src/examples/parity/parity.c")
target_link_libraries(app PRIVATE neat)
CMAKE
  run_quiet cmake -S "$d/src" -B "$d/build" "${gen[@]}" -DCMAKE_C_COMPILER="$cc"
  run_quiet cmake --build "$d/build"
  # the parent's program where the parent puts it, not in neat-duel's bin/; no tests or tools of neat-duel
  [[ -x $d/build/app ]] || fail "app not in the parent's build directory"
  [[ ! -e $d/build/neat-duel/bin ]] || fail "neat-duel built programs in a parent project"
  if grep -q "duel_evolve\|test_pop" "$d/build/build.ninja" 2> /dev/null; then fail "tools or tests built as a subproject"; fi
  run_parity "$d/build/app"
  ;;
*)
  fail "unknown step $step"
  ;;
esac
