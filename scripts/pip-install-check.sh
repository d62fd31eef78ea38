#!/usr/bin/env bash
# The Python package as a user installs it, offline: a virtual environment over
# Debian's packages (numpy, setuptools, wheel), pip install --no-build-isolation
# from the repository root, then the README's one-liner from another folder.
# RDMESH_CMAKE_BUILD_DIR=DIR reuses a configured build (the ctest does); without
# it pip configures and builds build-pip/cmake (what a fresh clone does).
# RDMESH_PYTHON: the interpreter that makes the venv (default python3).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"${RDMESH_PYTHON:-python3}" -m venv --system-site-packages "$work/v"
PIP_NO_INDEX=1 "$work/v/bin/pip" install --no-build-isolation --quiet --disable-pip-version-check "$root"
cd "$work"
out="$("$work/v/bin/python" -c "import rdmesh; print(rdmesh.mesh_implicit('x^2+y^2+z^2-1',
bbox=(-1.2,)*3+(1.2,)*3, size=0.2).tets.shape)")"
echo "$out"
"$work/v/bin/python" -c "import rdmesh, sys; sys.exit(0 if rdmesh.__file__.startswith('$work/v/') else 'rdmesh imported from ' + rdmesh.__file__)"
[[ "$out" =~ ^\([1-9][0-9]*,\ 4\)$ ]] || { echo "pip-install-check: unexpected output '$out'" >&2; exit 1; }
