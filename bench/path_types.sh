#!/bin/sh
# Caustics by path tracing and by BDPT at equal samples per pixel: the image mean, the mean
# per-pixel variance and the render time (render.json) of the full image and of its LS+DE part,
# on the Cornell box with the glass sphere and mirror. Prints a Markdown table (docs/benchmarks.md,
# "Bidirectional path tracing") and writes bench/path_types_results/caustics_bdpt_vs_path.png,
# the two LS+DE images side by side at BDPT's exposure.
# Usage: bench/path_types.sh [BUILD_DIR] [SPP] [SIZE]
set -eu
build=${1:-build}
spp=${2:-16}
size=${3:-128}
scene=data/cornell_box/cornell_box_mirror_glass.obj
camera=data/cornell_box/cornell_box.camera.json  # the variant shares the box and its camera
results=bench/path_types_results
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
mkdir -p "$results"
echo "| method | --paths | spp | mean radiance (R,G,B) | mean pixel variance | render s |"
echo "| --- | --- | --- | --- | --- | --- |"
for paths in "" "LS+DE"; do
  exposure=""
  for method in bdpt path; do
    dir="$out/$method$paths"
    "$build/bin/radiosity" render "$scene" --camera "$camera" --method "$method" \
      ${paths:+--paths "$paths"} ${exposure:+--exposure "$exposure"} \
      --spp "$spp" --width "$size" --height "$size" --out "$dir" -q
    python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
m = ", ".join("%.4f" % v for v in r["mean_radiance"])
print("| %s | %s | %s | %s | %.3g | %.2f |" % (sys.argv[2], sys.argv[3] or "(all)", sys.argv[4], m,
                                        r["mean_pixel_variance"], r["time_seconds"]["render"]))' \
      "$dir/render.json" "$method" "$paths" "$spp"
    # The path tracer's image at BDPT's exposure, so the two compare pixel for pixel.
    exposure=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["tone_map"]["exposure"])' \
      "$dir/render.json")
  done
done
/usr/bin/python3 - "$out/bdptLS+DE/render.png" "$out/pathLS+DE/render.png" \
  "$results/caustics_bdpt_vs_path.png" "$spp" <<'PY'
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.image as image
import matplotlib.pyplot as plt
fig, axes = plt.subplots(1, 2, figsize=(6, 3.2))
for ax, path, title in zip(axes, sys.argv[1:3], ["bdpt", "path"]):
    ax.imshow(image.imread(path))
    ax.set_title("%s, LS+DE, %s spp" % (title, sys.argv[4]))
    ax.axis("off")
fig.tight_layout()
fig.savefig(sys.argv[3], dpi=100)
PY
