#!/usr/bin/env bash
# Installs the dependencies (with the independent references: Blender, the glTF validator), builds,
# and runs the whole test suite (every label, slow included) through scripts/run_tests.sh, which
# fails when a test the sources define is not registered, when no test or fewer than selected ran,
# and under CI=true when any test was skipped.
# Arguments go to ctest: CI passes `-LE slow` (the real scenes take tens of minutes).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --references
bash scripts/build.sh
bash scripts/run_tests.sh build --output-on-failure -j"$(nproc)" --timeout 900 "$@"
