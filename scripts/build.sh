#!/usr/bin/env bash
# Configures and builds rdmesh into build/ (or $RDMESH_BUILD_DIR) with 2 jobs.
# Extra arguments, and those in $RDMESH_CMAKE_ARGS, go to cmake's configure step
# (e.g. -DRDMESH_SANITIZE=ON).
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${RDMESH_BUILD_DIR:-build}
# shellcheck disable=SC2086  # RDMESH_CMAKE_ARGS is a list of words
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release ${RDMESH_CMAKE_ARGS:-} "$@" >/dev/null
cmake --build "$dir" -j "${RDMESH_JOBS:-2}"
