#!/usr/bin/env bash
# Fuzzes the project's parsers with libFuzzer (clang, AddressSanitizer + UBSan).
#   bash scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]
# Targets: obj_scene (OBJ + MTL through loadObjScene, the scene limits and meshing),
# camera_json (the camera sidecar through loadCamera and findSceneCamera), lights_json (the lights
# file through loadLights and findSceneLights), gltf_scene (glTF 2.0, .gltf + .bin or .glb,
# through loadScene and loadGltfCamera), texture_image (image bytes through decodeTexture, as MTL
# and glTF textures reach it), scene_overrides (relight's override file through
# loadSceneOverrides), kept_factors (factors.bin of solve --keep-factors through
# readKeptFactors), probes_bin (probes.bin of solve --probes through readProbesBinary),
# saved_solution (solution.json and its elements CSV through loadSavedSolution) and, where
# VTK is installed, solution_vtp
# (a saved solution.vtp through the viewer's reader and what the viewer computes from it).
# Default: 60 s each, every target the build has, FUZZ_JOBS (default: the cores) at a time. Each run starts from the
# seed corpus in tests/fuzz/corpus/<target> and keeps what it finds in $BUILD/corpus/<target>
# (reused by the next run). A crash, a sanitizer report, a leak, an unexpected exception or an
# input slower than 10 s is written to $BUILD/artifacts/<target>/, its path is printed, and the
# script exits non-zero. Environment: FUZZ_BUILD (default build-fuzz), JOBS (build jobs, 2).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
build="${FUZZ_BUILD:-build-fuzz}"

bash scripts/setup.sh --fuzz
if [ ! -f "$build/CMakeCache.txt" ]; then
  launcher=()
  if command -v ccache >/dev/null 2>&1; then
    launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  fi
  CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRADIOSITY_FUZZ=ON \
    -DRADIOSITY_TESTS=OFF "${launcher[@]}" >/dev/null
fi
if [ ${#targets[@]} -eq 0 ]; then
  # Every libFuzzer target this build defines (solution_vtp only where VTK was found).
  mapfile -t targets < <(cmake --build "$build" --target help | grep -oE '\bfuzz_[a-z_]+' |
                           grep -v '^fuzz_replay_' | sed 's/^fuzz_//' | sort -u)
fi
cmake --build "$build" -j"${JOBS:-2}" --target $(printf 'fuzz_%s ' "${targets[@]}")

# Third-party leaks (each with its reason) are suppressed; any other leak is a finding.
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizer/lsan.supp:print_suppressions=0"
# One target per core at a time (FUZZ_JOBS, default nproc): each still fuzzes for its own
# SECONDS on its own core, in a fraction of the wall time of one after the other.
fuzz_one() {
  local t=$1
  mkdir -p "$build/corpus/$t" "$build/artifacts/$t"
  local dict=()
  [ -f "tests/fuzz/$t.dict" ] && dict=(-dict="tests/fuzz/$t.dict")
  echo "fuzz: $t for ${seconds} s"
  local log="$build/fuzz_$t.log"
  local before
  before=$(ls "$build/artifacts/$t" | wc -l)
  if "$build/bin/fuzz_$t" "$build/corpus/$t" "tests/fuzz/corpus/$t" "${dict[@]}" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
      -print_final_stats=1 -artifact_prefix="$build/artifacts/$t/" >"$log" 2>&1; then
    echo "fuzz: $t: $(grep -o 'Done [0-9]* runs in [0-9]* second(s)' "$log" | tail -1), no finding"
    return 0
  fi
  {
    tail -n 60 "$log"
    echo "fuzz: $t FAILED (log: $log)"
    # The reproducers libFuzzer wrote (crash-*, leak-*, timeout-*, oom-*), newest first.
    if [ "$(ls "$build/artifacts/$t" | wc -l)" -gt "$before" ]; then
      for f in $(ls -t "$build/artifacts/$t"); do
        echo "fuzz: reproducer $build/artifacts/$t/$f (replay: $build/bin/fuzz_$t $build/artifacts/$t/$f)"
      done
    fi
  } | flock "$build/fuzz.lock" cat  # one failure's lines together
  return 1
}
parallel="${FUZZ_JOBS:-$(nproc)}"
status=0
running=0
for t in "${targets[@]}"; do
  if [ "$running" -ge "$parallel" ]; then
    wait -n || status=1
    running=$((running - 1))
  fi
  fuzz_one "$t" &
  running=$((running + 1))
done
while [ "$running" -gt 0 ]; do
  wait -n || status=1
  running=$((running - 1))
done
exit $status
