#!/usr/bin/env bash
# The main job: install, build, and solve the bundled Cornell box into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/bin/radiosity solve data/cornell_box/cornell_box.obj --out out "$@"
