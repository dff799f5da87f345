#!/usr/bin/env bash
# Builds the library, tools and tests with AddressSanitizer + UndefinedBehaviorSanitizer
# (-DRADIOSITY_SANITIZE=ON, into build-asan) and runs the unit tests under them; any report
# fails the run.
#   bash scripts/sanitize.sh          # GCC
#   bash scripts/sanitize.sh --fuzz   # clang, with the libFuzzer targets in the same build, so
#                                     # scripts/fuzz.sh can reuse it (.ci/run: ASAN_BUILD=build-fuzz)
# Environment: ASAN_BUILD (default build-asan), JOBS (build jobs, 2), LABEL (ctest label,
# default unit; "" runs everything); scripts/run_tests.sh runs them, so a label that selects
# nothing, or a test the build does not register, fails. ccache is used where it is installed (CCACHE_DISABLE=1
# turns it off). LeakSanitizer reports of third-party libraries are suppressed by
# tests/sanitizer/lsan.supp (each entry says why); the project's own leaks are not.
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
if command -v ccache >/dev/null 2>&1; then
  flags+=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
# The compiler is fixed when a build directory is first configured: one directory per choice.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRADIOSITY_TESTS=ON \
  -DRADIOSITY_VIEWER=ON -DRADIOSITY_REQUIRE_VIEWER=ON "${flags[@]}" >/dev/null
cmake --build "$build" -j"${JOBS:-2}"
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizer/lsan.supp:print_suppressions=0"
label="${LABEL-unit}"
bash scripts/run_tests.sh "$build" ${label:+-L "$label"} --output-on-failure -j2
