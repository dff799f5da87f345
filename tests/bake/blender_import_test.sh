#!/bin/sh
# ctest driver for scripts/blender_import_check.py: bakes a small Cornell box and imports the .glb
# into headless Blender. Exits 77 (ctest SKIP_RETURN_CODE) when `blender` is not on PATH.
# Usage: blender_import_test.sh RADIOSITY_BINARY SOURCE_DIR SCRATCH_DIR
set -eu
radiosity=$1 source=$2 scratch=$3
if ! command -v blender >/dev/null 2>&1; then
  echo "blender is not on PATH: the Blender import check is skipped"
  # Under CI=true an external reference may not be skipped (scripts/setup.sh --references).
  [ "${CI:-}" = true ] && exit 1
  exit 77
fi
rm -rf "$scratch"
"$radiosity" bake "$source/data/cornell_box/cornell_box.obj" --out "$scratch" \
  --elements 300 --rays 64 --lightmap-size 128 --quiet
blender -b --factory-startup --python-exit-code 1 \
  --python "$source/scripts/blender_import_check.py" -- "$scratch/scene_baked.glb"
rm -rf "$scratch"
