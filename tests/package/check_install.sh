#!/usr/bin/env bash
# cmake --install BUILD into a temporary prefix, then configure, build and run
# the external consumer project (tests/package) against it.
set -euo pipefail
build="$(cd "$1" && pwd)"
src="$(cd "$(dirname "$0")/../.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
test -f "$work/prefix/lib/cmake/rdmesh/rdmeshConfig.cmake"
test -f "$work/prefix/include/rdmesh/mesher.h"
test -x "$work/prefix/bin/rdmesh"
# The installed command finds its CAD module (LIBDIR/rdmesh) from its own folder.
module=$(find "$work/prefix" -name rdmesh_cad_module.so)
test -n "$module"
"$work/prefix/bin/rdmesh" "$src/samples/plate_with_hole.step" -q -o "$work/plate.mesh"
test -s "$work/plate.mesh"
cmake -S "$src/tests/package" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$work/prefix" -DRDMESH_SAMPLES_DIR="$src/samples" >/dev/null
cmake --build "$work/consumer" -j "${RDMESH_JOBS:-2}" >/dev/null
"$work/consumer/custom_oracle" "$work/ball.mesh"
"$work/consumer/cad_volumes" "$src/samples/plate_with_hole.step"
echo "check_install: the installed package builds and runs an external project"
