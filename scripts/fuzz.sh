#!/usr/bin/env bash
# Fuzzes the project's parsers with libFuzzer (clang, AddressSanitizer + UBSan).
#   bash scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]
# Targets: obj_scene (OBJ + MTL through loadObjScene, the scene limits and meshing) and
# camera_json (the camera sidecar through loadCamera). Default: 60 s each, all targets, one
# after the other. Each run starts from the seed corpus in tests/fuzz/corpus/<target> and keeps
# what it finds in $BUILD/corpus/<target> (reused by the next run). A crash, a sanitizer report,
# an unexpected exception or an input slower than 10 s is written to $BUILD/artifacts/<target>/
# and fails the script. Environment: FUZZ_BUILD (default build-fuzz), JOBS (build jobs, 2).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(obj_scene camera_json)
build="${FUZZ_BUILD:-build-fuzz}"

bash scripts/setup.sh --fuzz
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRADIOSITY_FUZZ=ON \
    -DRADIOSITY_TESTS=OFF -DRADIOSITY_VIEWER=OFF >/dev/null
fi
cmake --build "$build" -j"${JOBS:-2}" --target $(printf 'fuzz_%s ' "${targets[@]}")

status=0
for t in "${targets[@]}"; do
  mkdir -p "$build/corpus/$t" "$build/artifacts/$t"
  dict=()
  [ -f "tests/fuzz/$t.dict" ] && dict=(-dict="tests/fuzz/$t.dict")
  echo "fuzz: $t for ${seconds} s"
  log="$build/fuzz_$t.log"
  # -close_fd_mask=2: the loaders' warnings would flood the log; libFuzzer reports on its own fd.
  if "$build/bin/fuzz_$t" "$build/corpus/$t" "tests/fuzz/corpus/$t" "${dict[@]}" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
      -close_fd_mask=2 -print_final_stats=1 -artifact_prefix="$build/artifacts/$t/" >"$log" 2>&1; then
    echo "fuzz: $t: $(grep -o 'Done [0-9]* runs in [0-9]* second(s)' "$log" | tail -1), no finding"
  else
    status=1
    tail -n 40 "$log"
    echo "fuzz: $t FAILED; the input is in $build/artifacts/$t/ (replay: $build/bin/fuzz_$t FILE)"
  fi
done
exit $status
