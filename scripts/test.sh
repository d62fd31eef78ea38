#!/usr/bin/env bash
# Quick start 2: install what is missing, build, run the whole test suite.
# --sanitize: build in build-asan with ASan+UBSan and the debug checks
# (RDMESH_DEBUG_ASSERT on the invariants) and run the whole suite there too (slow
# and CAD tests included: about 2.5 minutes on 2 cores).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
if [ "${1:-}" = "--sanitize" ]; then
  # libfreeimage (pulled in by OpenCASCADE's XCAF and visualization toolkits,
  # which the STEP names and colours need) frees at exit with free() what it
  # allocated with new: not ours, and it aborts every test executable, also at
  # test discovery during the build.
  export ASAN_OPTIONS=alloc_dealloc_mismatch=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}
  RDMESH_BUILD_DIR=build-asan bash scripts/build.sh -DRDMESH_SANITIZE=ON -DRDMESH_DEBUG_CHECKS=ON \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo
  ctest --test-dir build-asan --output-on-failure
else
  bash scripts/build.sh
  ctest --test-dir build --output-on-failure
fi
