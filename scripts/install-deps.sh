#!/usr/bin/env bash
# Installs the Debian 12 packages rdmesh needs to build, test and benchmark.
# Runs apt-get only for what is missing; uses sudo when not root.
# --fuzz: also what scripts/fuzz.sh needs; --sanitize: what scripts/test.sh --sanitize
# needs (clang); --format: what scripts/check-format.sh needs.
set -euo pipefail
packages=(
  build-essential cmake ccache pkg-config git
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev libeigen3-dev
  libmuparser-dev nlohmann-json3-dev libcli11-dev libgtest-dev
  libpng-dev zlib1g-dev  # view/: PNG pictures, zlib-compressed .vtu input
  python3-meshio gmsh   # independent readers used by the round-trip tests
  libmetis-dev          # --partitions: METIS on the tetrahedra's dual graph
  # The Python module (python/): headers, pybind11, numpy; pytest runs tests/python;
  # venv, setuptools and wheel make `pip install --no-build-isolation .` work offline.
  python3-dev pybind11-dev python3-numpy python3-pytest python3-venv python3-setuptools
  python3-wheel
  # OpenCASCADE for cad/ (STEP/IGES need data-exchange, whose CMake config also
  # wants the ocaf and visualization dev packages; TKernel links TBB). The STEP
  # names and colours (XCAF) pull in TKService, whose exported link interface
  # names -lfontconfig: libocct-visualization-dev does not depend on its dev
  # package, and a bare Debian root failed to link without it.
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev libocct-ocaf-dev libocct-visualization-dev libtbb-dev
  libfontconfig-dev
)
if [ "${1:-}" = "--fuzz" ] || [ "${1:-}" = "--sanitize" ]; then
  # Fuzzing and the sanitizer build (scripts/fuzz.sh, scripts/test.sh --sanitize):
  # clang 14 and its compiler runtime, which ships libFuzzer
  # (libclang_rt.fuzzer-x86_64.a) and the sanitizer runtimes.
  packages+=(clang libclang-rt-14-dev)
fi
if [ "${1:-}" = "--format" ]; then
  packages+=(clang-format-14)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "rdmesh: installing ${missing[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
