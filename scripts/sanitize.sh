#!/usr/bin/env bash
# Builds the library, tools and tests with AddressSanitizer + UndefinedBehaviorSanitizer
# (-DRADIOSITY_SANITIZE=ON, into build-asan) and runs the unit tests under them; any report
# fails the run.
#   bash scripts/sanitize.sh          # GCC
#   bash scripts/sanitize.sh --fuzz   # clang, with the libFuzzer targets in the same build, so
#                                     # FUZZ_BUILD=build-asan bash scripts/fuzz.sh reuses it (CI)
# Environment: ASAN_BUILD (default build-asan), JOBS (build jobs, 2), LABEL (ctest label,
# default unit; "" runs everything).
set -euo pipefail
cd "$(dirname "$0")/.."
build="${ASAN_BUILD:-build-asan}"
if [ "${1:-}" = "--fuzz" ]; then
  bash scripts/setup.sh --fuzz
  export CC=clang CXX=clang++
  flags=(-DRADIOSITY_FUZZ=ON)
else
  bash scripts/setup.sh
  flags=(-DRADIOSITY_SANITIZE=ON)
fi
# The compiler is fixed when a build directory is first configured: one directory per choice.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${flags[@]}" -DRADIOSITY_VIEWER=OFF >/dev/null
cmake --build "$build" -j"${JOBS:-2}"
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
label="${LABEL-unit}"
ctest --test-dir "$build" ${label:+-L "$label"} --output-on-failure -j2
