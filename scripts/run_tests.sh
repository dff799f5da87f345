#!/usr/bin/env bash
# Runs ctest on a build directory so that it cannot pass on fewer tests than the project has:
#   bash scripts/run_tests.sh BUILD_DIR [CTEST_ARGS...]     (e.g. -LE slow, -L unit, -j2)
# 1. scripts/check_test_registration.py: every test the sources define is registered in BUILD_DIR,
#    each with one label (a folder dropped from the build, a renamed label fail here);
# 2. the selection (CTEST_ARGS) must hold at least one test, and ctest runs with --no-tests=error;
# 3. the count ctest ran must equal the count the selection registered;
# 4. under CI=true, a skipped test (an external reference whose tool is missing: Blender, the
#    glTF validator's node, Xvfb) is a failure, named with the reason its output gives.
set -euo pipefail
cd "$(dirname "$0")/.."
build=$1
shift

python3 scripts/check_test_registration.py "$build"

selected=$(ctest --test-dir "$build" -N "$@" | sed -n 's/^Total Tests: \([0-9]*\)$/\1/p')
if [ -z "$selected" ] || [ "$selected" -eq 0 ]; then
  echo "run_tests: no test in $build matches: $*" >&2
  exit 1
fi

log=$(mktemp)
trap 'rm -f "$log"' EXIT
status=0
ctest --test-dir "$build" --no-tests=error "$@" 2>&1 | tee "$log" || status=$?
[ "$status" -eq 0 ] || exit "$status"

ran=$(sed -n 's/.*tests passed, [0-9]* tests failed out of \([0-9]*\)$/\1/p' "$log" | tail -n 1)
if [ "$ran" != "$selected" ]; then
  echo "run_tests: ctest ran ${ran:-no} tests of the $selected selected in $build ($*)" >&2
  exit 1
fi

if [ "${CI:-}" = "true" ]; then
  skipped=$(sed -n '/The following tests did not run:/,/^$/p' "$log" | grep -E '\((Skipped|Not Run)\)' || true)
  if [ -n "$skipped" ]; then
    echo "run_tests: under CI=true every test must run; these were skipped (their output above says why):" >&2
    echo "$skipped" >&2
    exit 1
  fi
fi
echo "run_tests: $ran of $selected selected tests ran in $build"
