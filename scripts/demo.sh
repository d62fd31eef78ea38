#!/usr/bin/env bash
# Quick start 1: install what is missing, build, mesh the bundled sample with defaults.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
build/cli/rdmesh samples/sphere.json -o sphere.msh --report sphere-report.json
