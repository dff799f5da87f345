#!/usr/bin/env bash
# Installs the dependencies (Debian packages) and builds in Release into build/, with warnings as
# errors (RADIOSITY_WERROR=OFF in the environment turns that off).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRADIOSITY_WERROR="${RADIOSITY_WERROR:-ON}"
cmake --build build -j"$(nproc)"
