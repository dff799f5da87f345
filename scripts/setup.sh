#!/usr/bin/env bash
# Installs the Debian 12 packages the project builds against. Idempotent, no prompts.
# Run as root (or with sudo available). Skips apt entirely when everything is present.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libopenmesh-dev      # half-edge mesh for patches/elements
  libembree-dev        # ray casting (form factors, visibility)
  libeigen3-dev        # sparse matrices, direct reference solve
  libtbb-dev           # parallel form-factor rows
  libtinyobjloader-dev # OBJ + MTL with Ke, materials, groups
  nlohmann-json3-dev   # summary.json
  libcli11-dev         # command-line parsing
  libopenexr-dev       # HDR images (EXR)
  libstb-dev           # PNG writer (stb_image_write); TGA and HDR textures (stb_image)
  libpng-dev           # PNG textures
  libjpeg62-turbo-dev  # JPEG textures
  libopenimageio-dev   # BMP (every variant) and TIFF textures
  libgtest-dev         # tests
  libtinygltf-dev      # glTF 2.0 export (radiosity bake)
  libvtk9-dev xvfb xauth # viewer (radiosity view, solution.vtp); Xvfb for off-screen screenshots
  zlib1g-dev           # deflates the PNGs written; the viewer inflates solution.vtp's blocks to check them
  python3              # scripts/check_test_registration.py; the Python test drivers in tests/bench, tests/slow
)
# The Khronos glTF validator (tools/gltf-validator, pinned by its package-lock.json) runs on node;
# Debian's nodejs and npm, unless a node and npm are already on PATH.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  packages+=(nodejs npm)
fi
# `scripts/setup.sh --fuzz`: clang and its libFuzzer runtime too (scripts/fuzz.sh; issue 9).
if [[ " $* " == *" --fuzz "* ]]; then packages+=(clang libclang-rt-14-dev); fi
# `scripts/setup.sh --format`: clang-format for the formatting check (scripts/check_format.sh).
if [[ " $* " == *" --format "* ]]; then packages+=(clang-format); fi
# `scripts/setup.sh --references`: the independent references of the test suite that the project
# did not write: Blender 3.4 (its glTF importer reads the baked .glb; Cycles checks the race's
# conventions) and numpy (the bake conventions test). scripts/test.sh asks for them: the whole
# suite runs them, and under CI=true a skipped external check fails CI (scripts/run_tests.sh).
if [[ " $* " == *" --references "* ]]; then packages+=(blender python3-numpy); fi
# `scripts/setup.sh --bench`: matplotlib for the benchmark's PNG plots (bench/run_all.sh; issue 8)
# and Blender (3.4), whose Cycles the side-by-side race renders with (bench/peer/race.py; issue 17);
# oiiotool, which reads the lightmaps' EXR texels for bench/leak_suite.py (issue 48).
if [[ " $* " == *" --bench "* ]]; then
  packages+=(python3-matplotlib python3-numpy blender openimageio-tools)
fi

# The Khronos glTF validator for the bake tests (npm, pinned by tools/gltf-validator/package-lock.json).
install_gltf_validator() {
  local dir
  dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/tools/gltf-validator"
  if [ ! -d "$dir/node_modules/gltf-validator" ]; then
    echo "setup: installing the glTF validator into $dir"
    npm ci --prefix "$dir" --no-audit --no-fund --loglevel=error
  fi
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed"
  install_gltf_validator
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
install_gltf_validator
