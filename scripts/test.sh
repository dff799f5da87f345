#!/usr/bin/env bash
# Installs the dependencies, builds, and runs the whole test suite (every label, slow included).
# Arguments go to ctest: CI passes `-LE slow` (the real scenes take tens of minutes).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 900 "$@"
