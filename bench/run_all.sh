#!/usr/bin/env bash
# The whole issue-8 benchmark in one command, on the 2-core development machine:
#   1. ray throughput: form-factor rows against raw Embree on the same rays, 1…all threads
#      (ratio and parallel scaling)                               → bench/results/throughput.*
#   2. run time against error: Cornell box, its mirror/glass variant and a generated room
#                                                                 → bench/results/time_vs_error_*
#   3. cost growth with scene size, 1e3 … 1e5 elements           → bench/results/growth.*
#   4. uniform against adaptive meshing (bench/mesh_error)       → bench/mesh_results/
#   5. render error against time (bench/render_error_vs_time.py) → bench/render_results/
#   6. leaks and dark contacts of default bakes (bench/leak_suite.py) → bench/results/leak_suite.csv
#
#   bash bench/run_all.sh [BUILD_DIR]     (default: build; configured here when it has no cache)
#
# Plots are PNG (matplotlib from Debian's python3-matplotlib, installed by setup.sh --bench).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
OUT=bench/results
PY=/usr/bin/python3
start=$(date +%s)
stage() { echo "== run_all: $1 (at $(($(date +%s) - start)) s)" >&2; }

stage "setup (python3-matplotlib)"
if ! bash scripts/setup.sh --bench >&2; then
  "$PY" -c "import matplotlib" 2>/dev/null ||
    { echo "run_all: matplotlib is missing and scripts/setup.sh --bench failed" >&2; exit 1; }
  echo "run_all: setup.sh --bench failed, but matplotlib is present: going on" >&2
fi

stage "build"
if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >&2
fi
cmake --build "$BUILD" --target radiosity throughput time_vs_error mesh_error render_compare -j"$(nproc)" >&2
mkdir -p "$OUT"

stage "ray throughput"
"$BUILD/bin/throughput" --benchmark_format=json --benchmark_min_time=1 --benchmark_repetitions=5 \
  --benchmark_report_aggregates_only=true >"$OUT/throughput.json.tmp"
mv "$OUT/throughput.json.tmp" "$OUT/throughput.json"
"$PY" bench/throughput_table.py "$OUT/throughput.json" "$OUT/throughput.csv"

stage "time against error"
SCENES=$(mktemp -d)
trap 'rm -rf "$SCENES"' EXIT
"$PY" bench/scene_generator.py "$SCENES/room.obj" --boxes 16
rm -f "$OUT"/time_vs_error_*.csv
# Cornell box: analytic reference at 3000 elements (the defaults).
"$BUILD/bin/time_vs_error" data/cornell_box/cornell_box.obj --name cornell_box --out "$OUT"
# Mirror and glass: hemisphere rows only (analytic form factors do not follow specular paths).
"$BUILD/bin/time_vs_error" data/cornell_box/cornell_box_mirror_glass.obj --name mirror_glass --out "$OUT" \
  --reference-rays 4096
# Generated room (16 boxes): larger meshes; the analytic method, whose cost is elements × patches,
# only up to 2000 elements, and a hemisphere reference.
"$BUILD/bin/time_vs_error" "$SCENES/room.obj" --name generated_room --out "$OUT" \
  --elements 1000,4000,16000 --rays 32,128,512 --analytic-elements 500,1000,2000 \
  --reference hemisphere --reference-elements 16000 --reference-rays 1024
"$PY" bench/plot_time_vs_error.py "$OUT"

stage "cost growth"
"$PY" bench/growth.py --build "$BUILD" --out "$OUT"

stage "uniform against adaptive meshing (bench/mesh_error)"
mkdir -p bench/mesh_results
"$BUILD/bin/mesh_error" --out bench/mesh_results

stage "render error against time (bench/render_error_vs_time.py)"
"$PY" bench/render_error_vs_time.py --build "$BUILD"

stage "leaks and dark contacts (bench/leak_suite.py)"
"$PY" bench/leak_suite.py

stage "done"
