#!/usr/bin/env bash
# Installs the dependencies (Debian packages) and builds in Release into build/, with warnings as
# errors (RADIOSITY_WERROR=OFF in the environment turns that off). The tests and the viewer are
# forced on (a RADIOSITY_TESTS=OFF cached in build/ would otherwise leave ctest nothing to run;
# setup.sh installs VTK, so its absence is an error, not a smaller build).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRADIOSITY_WERROR="${RADIOSITY_WERROR:-ON}" \
  -DRADIOSITY_TESTS=ON -DRADIOSITY_VIEWER=ON -DRADIOSITY_REQUIRE_VIEWER=ON
cmake --build build -j"$(nproc)"
