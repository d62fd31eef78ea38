#!/usr/bin/env bash
# Regenerates the README's pictures (docs/pictures/*.png), one per input kind:
# an implicit domain with two subdomains, a sharp-featured implicit domain and
# a STEP part, each meshed with its defaults. Run it after a change that moves
# meshes or pictures, look at the PNGs, and commit them.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
out=docs/pictures
mkdir -p "$out"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for input in samples/nested_spheres.json samples/capped_cylinder.json samples/plate_with_hole.step; do
  name=$(basename "${input%.*}")
  build/cli/rdmesh "$input" -o "$scratch/$name.msh" --picture "$out/$name.png" --picture-size 1200x600 -q
  echo "$out/$name.png"
done
