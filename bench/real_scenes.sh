#!/usr/bin/env bash
# Real scenes at the defaults: wall time and peak memory of `solve` and of `bake` (which solves,
# then bakes) on the shared atrium (Sponza, lit by a sky and a sun), the shared staircase (13 area
# lights, two-sided) and the large generated atrium (bench/atrium_scene.py --size large).
#
#   bash bench/real_scenes.sh [BUILD_DIR]        (default: build)
#
# The shared scenes are read from $RADIOSITY_SCENES (default ../shared/scenes, beside the
# repository); a missing one is reported and skipped. Each command runs under /usr/bin/time -v
# with a limit of $REAL_SCENES_TIMEOUT seconds (default 1800). Results: bench/results/real_scenes.csv
# (one row per command: its exit status, wall seconds and peak resident memory) and each run's
# log under $BUILD_DIR/real_scenes/.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SCENES=${RADIOSITY_SCENES:-../shared/scenes}
LIMIT=${REAL_SCENES_TIMEOUT:-1800}
RADIOSITY="$BUILD/bin/radiosity"
WORK="$BUILD/real_scenes"
CSV=bench/results/real_scenes.csv
[ -x "$RADIOSITY" ] || { echo "real_scenes: $RADIOSITY is missing: build it first" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "real_scenes: /usr/bin/time is missing (apt-get install time)" >&2; exit 1; }
mkdir -p "$WORK" bench/results

# The sky and sun that light Sponza (the atrium ships with no light): the generated atrium's.
SPONZA_LIGHTS=(--sky 0.35 0.45 0.65 --sun 0.3 -1 0.25 8 7.6 6.8)

echo "scene,faces,command,options,exit,wall_s,peak_rss_mib" >"$CSV.tmp"
measure() {  # measure NAME SCENE COMMAND OPTIONS...
  local name=$1 scene=$2 command=$3
  shift 3
  local dir="$WORK/$name/$command" log="$WORK/$name/$command.log"
  rm -rf "$dir"
  mkdir -p "$dir"
  echo "real_scenes: $name: radiosity $command $scene --out $dir $*" >&2
  local status=0
  # timeout inside /usr/bin/time, so that a run stopped at the limit still reports its time and memory.
  /usr/bin/time -v timeout "$LIMIT" "$RADIOSITY" "$command" "$scene" --out "$dir" "$@" >"$log" 2>&1 || status=$?
  local wall rss faces
  # /usr/bin/time's "Elapsed (wall clock) time (h:mm:ss or m:ss): 1:02.34".
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, t, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + t[i]; print s}' "$log")
  rss=$(awk -F': ' '/Maximum resident set size/ {printf "%.0f", $2 / 1024}' "$log")
  faces=$(grep -c '^f ' "$scene" || true)
  echo "$name,$faces,$command,\"$*\",$status,${wall:-},${rss:-}" >>"$CSV.tmp"
  echo "real_scenes: $name $command: exit $status, ${wall:-?} s, ${rss:-?} MiB" >&2
}

if [ -f "$SCENES/staircase2/staircase2.obj" ]; then
  # Its wallpaper walls face out of the room: two-sided surfaces where the build has them.
  two_sided=()
  if "$RADIOSITY" solve --help | grep -q -- '--two-sided'; then two_sided=(--two-sided); fi
  measure staircase "$SCENES/staircase2/staircase2.obj" solve "${two_sided[@]}"
  measure staircase "$SCENES/staircase2/staircase2.obj" bake "${two_sided[@]}"
else
  echo "real_scenes: $SCENES/staircase2/staircase2.obj is missing (set RADIOSITY_SCENES): skipped" >&2
fi
if [ -f "$SCENES/sponza-dabrovic/sponza.obj" ]; then
  measure atrium "$SCENES/sponza-dabrovic/sponza.obj" solve "${SPONZA_LIGHTS[@]}"
  measure atrium "$SCENES/sponza-dabrovic/sponza.obj" bake "${SPONZA_LIGHTS[@]}"
else
  echo "real_scenes: $SCENES/sponza-dabrovic/sponza.obj is missing (set RADIOSITY_SCENES): skipped" >&2
fi
# --flat: Kd = each texture's mean, so the solve's cost is the same whether or not the build reads
# map_Kd (without textures, Kd 1 1 1 would make every surface white).
/usr/bin/python3 bench/atrium_scene.py "$WORK/generated" --size large --flat >&2
two_sided=()
if "$RADIOSITY" solve --help | grep -q -- '--two-sided'; then two_sided=(--two-sided); fi
measure generated_atrium "$WORK/generated/atrium.obj" solve "${two_sided[@]}"
measure generated_atrium "$WORK/generated/atrium.obj" bake "${two_sided[@]}"
mv "$CSV.tmp" "$CSV"
cat "$CSV"
