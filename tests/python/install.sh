#!/usr/bin/env bash
# install.sh PYTHON SRC - the package as a user gets it: a wheel built from the source tree (pip's way for
# `pip install .`), and an sdist made from it and built again; each installed apart from the build tree and used.
# PYTHON is the test environment's (it has the build tools: python/requirements-test.txt), so nothing is
# downloaded: --no-build-isolation. The first build runs in a bare venv that has only what pyproject.toml's
# [build-system].requires names (build_env.py), as pip's build isolation would give it: a build step needing
# anything else fails here as it would for a user.
set -euo pipefail
py=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
use() { # use DIR: import the package installed in DIR (and not the build tree's) and evolve XOR for a moment
  (cd "$tmp" && env -u PYTHONPATH PYTHONPATH="$1" "$py" - "$1" <<'PY'
import sys, neat_duel as nd
assert nd.__file__.startswith(sys.argv[1]), nd.__file__
import neat_duel._core as c
assert c.__file__.startswith(sys.argv[1])
pop = nd.Population(nd.Params(pop_size=20, n_inputs=2, n_outputs=1), seed=1)
recs = pop.run(lambda g: sum(g.network().step([1.0, 0.0])) + 0.1, 3)
assert len(recs) == 3 and recs[-1]["evaluations"] == 60
import pathlib
pkg = pathlib.Path(nd.__file__).parent
assert (pkg / "py.typed").exists() and (pkg / "_core.pyi").exists(), sorted(p.name for p in pkg.iterdir())
# the guide's configuration files ship with it (neat_duel.data_path)
assert nd.Params.from_ini(nd.data_path("bench/xor.ini")).pop_size == 150
assert nd.DuelConfig.from_ini(nd.data_path("configs/quick.ini")).generations > 0
assert nd.data_path("configs/plans/small.ini").is_file()
print("ok", nd.__version__, pkg)
PY
  )
}
# 1. from the source tree, as `pip install .` does (its build directory kept out of the tree), with only the
#    declared build requirements
"$py" -m venv --without-pip "$tmp/iso"
iso_site=$("$tmp/iso/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
"$py" "$(dirname "$0")/build_env.py" "$src" "$iso_site" || fail "the build requirements are not all here"
"$py" -m pip --python "$tmp/iso/bin/python" wheel -q --disable-pip-version-check --no-build-isolation --no-deps \
  -w "$tmp/w1" --config-settings=build-dir="$tmp/b1" "$src" > "$tmp/w1.log" 2>&1 ||
  { tail -40 "$tmp/w1.log"; fail "pip wheel of the source tree, with only [build-system].requires"; }
wheel=$(ls "$tmp"/w1/neat_duel-*.whl) || fail "no wheel"
# one abi3 wheel for CPython 3.12 and later (nanobind's stable ABI); a version's own wheel before 3.12
case "$("$py" -c 'import sys; print(sys.version_info >= (3, 12))')" in
  True) want=cp312-abi3 ;;
  *) want=$("$py" -c 'import sys; print("cp%d%d-cp%d%d" % (sys.version_info[:2] * 2))') ;;
esac
case "$(basename "$wheel")" in *-"$want"-*) ;; *) fail "$(basename "$wheel"): not tagged $want" ;; esac
"$py" -m pip install -q --disable-pip-version-check --no-deps --target "$tmp/i1" "$tmp"/w1/neat_duel-*.whl
use "$tmp/i1"
# 2. an sdist, then a wheel of it (what pip does with `pip install neat_duel-V.tar.gz`)
"$py" -m build --sdist --no-isolation -o "$tmp/s" "$src" > "$tmp/sdist.log" 2>&1 || { cat "$tmp/sdist.log"; fail "sdist"; }
sdist=$(ls "$tmp"/s/neat_duel-*.tar.gz)
# it holds the sources, not build trees or runs
tar tzf "$sdist" > "$tmp/sdist.txt"
if grep -E '/(build[^/]*|runs)/' "$tmp/sdist.txt"; then fail "the sdist holds build output"; fi
grep -q "/libneat/src/neat_pop.c$" "$tmp/sdist.txt" || fail "the sdist lacks libneat"
"$py" -m pip wheel -q --disable-pip-version-check --no-build-isolation --no-deps -w "$tmp/w2" \
  --config-settings=build-dir="$tmp/b2" "$sdist" || fail "pip wheel of the sdist"
"$py" -m pip install -q --disable-pip-version-check --no-deps --target "$tmp/i2" "$tmp"/w2/neat_duel-*.whl
use "$tmp/i2"
echo "install: ok"
