#!/usr/bin/env bash
# Quick start 2: install what is missing, build, run the whole test suite
# (two tests at a time, as many as the build's jobs: $RDMESH_JOBS, default 2).
# --sanitize: build in build-asan with ASan+UBSan and the debug checks
# (RDMESH_DEBUG_ASSERT on the invariants) and run the whole suite there too (slow
# and CAD tests included). That build uses clang: GCC 12 with both sanitizers at
# -O2 -g took 222 s on core/src/level_protecting_balls.cpp where clang 14 takes
# 40 s, and the whole build over 35 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${RDMESH_JOBS:-2}
if [ "${1:-}" = "--sanitize" ]; then
  bash scripts/install-deps.sh --sanitize
  # libfreeimage (pulled in by OpenCASCADE's XCAF and visualization toolkits,
  # which the STEP names and colours need) frees at exit with free() what it
  # allocated with new: not ours, and it aborts every test executable, also at
  # test discovery during the build.
  export ASAN_OPTIONS=alloc_dealloc_mismatch=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}
  RDMESH_BUILD_DIR=build-asan bash scripts/build.sh -DRDMESH_SANITIZE=ON -DRDMESH_DEBUG_CHECKS=ON \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++
  ctest --test-dir build-asan --output-on-failure -j "$jobs"
else
  bash scripts/install-deps.sh
  bash scripts/build.sh
  ctest --test-dir build --output-on-failure -j "$jobs"
fi
