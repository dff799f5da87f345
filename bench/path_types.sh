#!/bin/sh
# Caustics by path tracing and by BDPT at equal samples per pixel: the image mean and the mean
# per-pixel variance (render.json) of the full image and of its LS+DE part, on the Cornell box
# with the glass sphere and mirror. Prints a Markdown table (README "Bidirectional path tracing").
# Usage: bench/path_types.sh [BUILD_DIR] [SPP] [SIZE]
set -eu
build=${1:-build}
spp=${2:-16}
size=${3:-128}
scene=data/cornell_box/cornell_box_mirror_glass.obj
camera=data/cornell_box/cornell_box.camera.json  # the variant shares the box and its camera
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| method | --paths | spp | mean radiance (R,G,B) | mean pixel variance | render s |"
echo "| --- | --- | --- | --- | --- | --- |"
for paths in "" "LS+DE"; do
  for method in path bdpt; do
    dir="$out/$method$paths"
    "$build/bin/radiosity" render "$scene" --method "$method" ${paths:+--paths "$paths"} \
      --camera "$camera" --spp "$spp" --width "$size" --height "$size" --out "$dir" -q
    python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
m = ", ".join("%.4f" % v for v in r["mean_radiance"])
print("| %s | %s | %s | %s | %.3g | %.2f |" % (sys.argv[2], sys.argv[3] or "(all)", sys.argv[4], m,
                                        r["mean_pixel_variance"], r["time_seconds"]["render"]))' \
      "$dir/render.json" "$method" "$paths" "$spp"
  done
done
