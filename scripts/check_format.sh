#!/usr/bin/env bash
# Checks that every tracked C++ file is formatted with the project's .clang-format (clang-format
# 14, Debian 12's). Prints the files that differ and exits 1 if any does; `clang-format -i FILE`
# fixes one.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --format >/dev/null
mapfile -t files < <(git ls-files '*.cpp' '*.h')
off=()
for f in "${files[@]}"; do
  if ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then off+=("$f"); fi
done
if [ ${#off[@]} -gt 0 ]; then
  printf 'check_format: %d of %d files differ from .clang-format:\n' "${#off[@]}" "${#files[@]}"
  printf '  %s\n' "${off[@]}"
  exit 1
fi
echo "check_format: all ${#files[@]} C++ files match .clang-format"
