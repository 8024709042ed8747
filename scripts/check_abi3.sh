#!/usr/bin/env bash
# check_abi3.sh [DIR] - the Python package on a CPython newer than Debian 12's 3.11: a Debian 13 (trixie,
# Python 3.13) chroot in DIR (default /tmp/abi3-check) gets this checkout (its last commit), builds the wheel with
# only the declared build requirements, checks it is the one cp312-abi3 wheel and uses it
# (tests/python/install.sh), audits its symbols against the stable ABI (abi3audit) and runs the package's pytest
# suite against it. Needs root, Debian's mirror and PyPI; 92 s here. Not part of the test suite: it downloads
# a distribution.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir=${1:-/tmp/abi3-check}
mkdir -p "$dir"
command -v debootstrap > /dev/null || apt-get install -y -q debootstrap
[ -x "$dir/root/usr/bin/apt-get" ] ||
  debootstrap --variant=minbase trixie "$dir/root" http://deb.debian.org/debian > "$dir/debootstrap.log" 2>&1
# a proxy's CA certificates, if this machine trusts extra ones, so that pip reaches PyPI from inside too
if compgen -G "/usr/local/share/ca-certificates/*.crt" > /dev/null; then
  mkdir -p "$dir/root/usr/local/share/ca-certificates"
  cp /usr/local/share/ca-certificates/*.crt "$dir/root/usr/local/share/ca-certificates/"
fi
mountpoint -q "$dir/root/proc" || mount -t proc proc "$dir/root/proc"
trap 'umount "$dir/root/proc"' EXIT
rm -rf "$dir/root/src"
git clone -q "$root" "$dir/root/src"
chroot "$dir/root" /bin/bash -euo pipefail -c '
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q > /dev/null
  apt-get install -y -q --no-install-recommends python3 python3-dev python3-venv build-essential cmake ninja-build \
    git ca-certificates > /dev/null
  update-ca-certificates > /dev/null 2>&1 || true
  python3 -V
  [ -x /venv/bin/python ] || python3 -m venv /venv
  /venv/bin/pip install -q --disable-pip-version-check scikit-build-core nanobind numpy build abi3audit
  cd /src && bash tests/python/install.sh /venv/bin/python /src
  rm -rf /wheels && /venv/bin/pip wheel -q --disable-pip-version-check --no-build-isolation --no-deps -w /wheels /src
  ls /wheels
  /venv/bin/abi3audit --verbose /wheels/neat_duel-*-cp312-abi3-*.whl
  # the package'"'"'s own tests against the installed wheel (those needing the C programs CTest names skip)
  rm -rf /venv2 && python3 -m venv /venv2
  /venv2/bin/pip install -q --disable-pip-version-check /wheels/neat_duel-*-cp312-abi3-*.whl pytest gymnasium
  cd /src/python/tests && /venv2/bin/python -m pytest -q -p no:cacheprovider . 2>&1 | tail -3
  /venv2/bin/python -c "import neat_duel; assert neat_duel.__file__.startswith(\"/venv2/\"), neat_duel.__file__"
'
echo "check_abi3: ok"
