#!/usr/bin/env bash
# Quick start 1: install what is missing, build, mesh the bundled STEP part with defaults
# (and draw it: plate_with_hole.png).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
build/cli/rdmesh samples/plate_with_hole.step -o plate_with_hole.msh --report plate_with_hole-report.json \
  --picture plate_with_hole.png
