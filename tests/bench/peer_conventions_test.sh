#!/bin/sh
# The side-by-side race (bench/peer/race.py) is only fair if its Cycles scene shows the physics the
# project computes: bench/peer/cycles_render.py renders the Cornell box with Cycles in two halves
# of 128 samples per pixel (seeds 1 and 2), and their mean must agree with the project's own
# path-traced reference (data/reference/cornell_box_path.exr, 2 x 2048 spp) once both images' noise
# is taken out (render_compare plain with both variance images: what is left is the systematic
# difference). Bounds, from the noise of that estimate (about 0.4% on the surfaces, docs/peer.md):
# surfaces' systematic error <= 1.5%, surfaces' and whole image's mean ratios within 1% of 1. A
# wrong convention fails it: emission read as power or exitance (x pi), a two-sided or a
# reflecting back face, Blender's Principled defaults (specular) instead of Lambert, the mirrored
# or flipped camera, a Gaussian pixel filter (blurs the light's outline).
# Exits 77 (ctest SKIP_RETURN_CODE) when `blender` is not on PATH.
# Usage: peer_conventions_test.sh RENDER_COMPARE SOURCE_DIR SCRATCH_DIR
set -eu
compare=$1 source=$2 scratch=$3
if ! command -v blender >/dev/null 2>&1; then
  echo "blender is not on PATH: the Cycles conventions check is skipped"
  exit 77
fi
rm -rf "$scratch"
mkdir -p "$scratch"
for seed in 1 2; do
  blender -b --factory-startup --python-exit-code 1 --python "$source/bench/peer/cycles_render.py" \
    -- "$source/data/cornell_box/cornell_box.obj" --camera "$source/data/cornell_box/cornell_box.camera.json" \
    --spp 128 --seed "$seed" --out "$scratch/cycles_$seed.exr" >"$scratch/blender_$seed.log" 2>&1 ||
    { cat "$scratch/blender_$seed.log"; exit 1; }
done
"$compare" halves "$scratch/cycles_1.exr" "$scratch/cycles_2.exr" "$scratch/cycles.exr" \
  "$scratch/cycles_variance.exr" >/dev/null
# whole (noise removed), whole raw, mean ratio, surfaces (noise removed), surfaces raw, their ratio
result=$("$compare" plain "$scratch/cycles.exr" "$source/data/reference/cornell_box_path.exr" \
  "$source/data/reference/cornell_box_path_variance.exr" "$scratch/cycles_variance.exr")
echo "Cycles 2 x 128 spp against the project's path tracer: $result"
echo "$result" | awk '{
  fail = 0
  if ($4 > 0.015) { print "FAILED: systematic error on the surfaces " $4 " > 0.015"; fail = 1 }
  if ($6 < 0.99 || $6 > 1.01) { print "FAILED: surfaces mean ratio " $6 " not within 1%"; fail = 1 }
  if ($3 < 0.99 || $3 > 1.01) { print "FAILED: image mean ratio " $3 " not within 1%"; fail = 1 }
  exit fail }'
rm -rf "$scratch"
