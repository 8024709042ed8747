#!/usr/bin/env bash
# Installs the Debian 12 packages the build, the tests and the benchmarks need, if any is missing (without their
# Recommends: 490 packages, 4.4 GB on a bare system, and 0.8 GB of downloaded files apt keeps; README, measured), the
# Python lcm package into a directory of its own, and the Python test environment.
set -euo pipefail
# What each group is for (a package the project does not use is not installed):
PKGS="build-essential cmake ninja-build pkg-config libcmocka-dev procps"           # the build and the unit tests
PKGS="$PKGS clang llvm libclang-rt-14-dev"                                          # the fuzzers (libFuzzer)
PKGS="$PKGS gcc-arm-none-eabi libnewlib-arm-none-eabi binutils-arm-none-eabi qemu-system-arm" # Cortex-M firmware
PKGS="$PKGS gcc-riscv64-unknown-elf picolibc-riscv64-unknown-elf qemu-system-misc" # RISC-V firmware
PKGS="$PKGS valgrind"                                                               # instruction counts (bench/)
PKGS="$PKGS graphviz fonts-dejavu-core libosmesa6-dev libpng-dev ffmpeg"            # network pictures, replays, videos
PKGS="$PKGS chromium chromium-driver python3-selenium"                              # the web pages' browser tests
PKGS="$PKGS liblcm-dev liblcm-bin liblcm-java libglib2.0-dev"                       # LCM nodes and logs
PKGS="$PKGS python3-matplotlib python3-pip"                                         # the experiment's figures; pip
PKGS="$PKGS python3-venv python3-dev"                                               # the Python package (python/)
PKGS="$PKGS openmpi-bin libopenmpi-dev"                                             # runs across processes (MPI)
# LCM's TCP hub (lcm.lcm.TCPService, the tests over tcpq://) runs on any Java runtime
command -v java > /dev/null 2>&1 || PKGS="$PKGS default-jre-headless"
SUDO=""
missing=""
for p in $PKGS; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ] && [ "$(id -u)" -ne 0 ]; then
  # not root: apt-get needs sudo, which a bare Debian 12 does not have
  if ! command -v sudo > /dev/null 2>&1; then
    echo "deps.sh: packages are missing and installing them needs root: run this as root (su -c ./scripts/setup.sh), or install sudo first (as root: apt-get install sudo; adduser $(id -un) sudo)" >&2
    exit 1
  fi
  SUDO="sudo"
fi
if [ -n "$missing" ]; then
  echo "installing:$missing"
  echo "(apt-get update, then one line per package set up; on a bare Debian 12 apt downloads 0.8 GB, then unpacks"
  echo " for a minute or two without a line, then sets up about 490 packages)"
  $SUDO apt-get update -qq
  # the Recommends would add the Arm C++ library, EFI firmware and more that nothing here uses
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends $missing |
    awk '/^Setting up / { print "  set up " $3; fflush() }'
fi
# The Python lcm package from PyPI, for the test that decodes a log in Python (tests/lcm/decode_log.py): into
# a directory of its own (CMake's NEAT_PY_LCM, the test's PYTHONPATH), so that its lcm-gen, lcm-logplayer and
# lcm-spy scripts are on nobody's PATH and never shadow Debian's.
py=/usr/bin/python3
[ -x "$py" ] || py=python3
pylcm=${NEAT_PY_LCM:-$HOME/.local/lib/neat-duel/python3}
if ! PYTHONPATH="$pylcm" "$py" -c 'import lcm' 2> /dev/null; then
  echo "installing: lcm==1.5.3 (PyPI) into $pylcm"
  mkdir -p "$pylcm"
  PIP_BREAK_SYSTEM_PACKAGES=1 "$py" -m pip install -q --no-deps --root-user-action=ignore --disable-pip-version-check \
    --upgrade --target "$pylcm" lcm==1.5.3 ||
    { echo "deps.sh: pip could not install lcm==1.5.3 from PyPI (above: no network to pypi.org, a proxy, or a TLS certificate this machine does not trust); the Debian packages are installed: fix that and run it again" >&2; exit 1; }
fi
# The Python package's build and tests (python/requirements-test.txt) in a virtual environment of their own
# (Debian's Python refuses system-wide pip installs): NEAT_PY_VENV, by default ~/.local/lib/neat-duel/venv. Made
# under a lock, so that two test suites started at once do not build it over each other.
venv=${NEAT_PY_VENV:-$HOME/.local/lib/neat-duel/venv}
req="$(cd "$(dirname "$0")/.." && pwd)/python/requirements-test.txt"
mkdir -p "$(dirname "$venv")"
(
  flock 9
  if ! cmp -s "$req" "$venv/requirements-test.txt" 2> /dev/null; then
    echo "installing: the Python test environment (python/requirements-test.txt, from PyPI) into $venv"
    rm -rf "$venv"
    "$py" -m venv "$venv"
    "$venv/bin/python" -m pip install -q --disable-pip-version-check -r "$req" ||
      { echo "deps.sh: pip could not install the Python test environment from PyPI (above); run it again once pypi.org is reachable" >&2; exit 1; }
    cp "$req" "$venv/requirements-test.txt"
  fi
) 9> "$venv.lock"
