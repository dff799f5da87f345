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
# Then the sky and the sun: a grey panel facing -x, seen whole, under `--sky` (it sees the upper
# half of the sky and a black ground) and under `--sun` (at 73 degrees from its normal), in both
# tools at 64 spp; the mean ratios must be within 1% (measured: noise of about 0.1%). A sky that
# also lights from below the horizon doubles the panel, a sun read as radiance or travelling the
# other way changes it by far more.
# Exits 77 (ctest SKIP_RETURN_CODE) when `blender` is not on PATH.
# Usage: peer_conventions_test.sh RENDER_COMPARE RADIOSITY SOURCE_DIR SCRATCH_DIR
set -eu
compare=$1 radiosity=$2 source=$3 scratch=$4
if ! command -v blender >/dev/null 2>&1; then
  echo "blender is not on PATH: the Cycles conventions check is skipped"
  # Under CI=true an external reference may not be skipped (scripts/setup.sh --references).
  [ "${CI:-}" = true ] && exit 1
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

printf 'v 0 -1 -1\nv 0 -1 1\nv 0 1 1\nv 0 1 -1\nf 1 2 3 4\n' >"$scratch/panel.obj"
printf '{"position": [-4, 0, 0], "look_at": [0, 0, 0], "up": [0, 1, 0], "vfov_degrees": 20, "width": 32, "height": 32}\n' \
  >"$scratch/panel.camera.json"
for light in "--sky 0.35 0.45 0.65" "--sun 0.3 -1 0.25 8 7.6 6.8"; do
  # shellcheck disable=SC2086 # the light's words are separate arguments
  blender -b --factory-startup --python-exit-code 1 --python "$source/bench/peer/cycles_render.py" \
    -- "$scratch/panel.obj" --camera "$scratch/panel.camera.json" --spp 64 --out "$scratch/panel_cycles.exr" \
    $light >"$scratch/blender_panel.log" 2>&1 || { cat "$scratch/blender_panel.log"; exit 1; }
  # shellcheck disable=SC2086
  "$radiosity" render "$scratch/panel.obj" --camera "$scratch/panel.camera.json" --method path --spp 64 \
    --out "$scratch/panel_project" -q $light
  ratio=$("$compare" rmse "$scratch/panel_project/render.exr" "$scratch/panel_cycles.exr" | awk '{print $2}')
  echo "panel under $light: mean ratio project / Cycles $ratio"
  echo "$ratio" | awk '{ if ($1 < 0.99 || $1 > 1.01) { print "FAILED: not within 1%"; exit 1 } }'
done
rm -rf "$scratch"
