#!/bin/sh
# ctest driver for a refusal: runs COMMAND, and passes only when it exits with exactly CODE (not
# 0, not a crash) and its output (stdout and stderr) matches the extended regular expression.
# Usage: expect_refusal.sh CODE REGEX COMMAND [ARGS...]
set -u
code=$1 pattern=$2
shift 2
output=$("$@" 2>&1)
status=$?
printf '%s\n' "$output"
if [ "$status" -ne "$code" ]; then
  echo "expect_refusal: exit $status, expected $code: $*"
  exit 1
fi
if ! printf '%s\n' "$output" | grep -Eq -e "$pattern"; then
  echo "expect_refusal: no line matches '$pattern'"
  exit 1
fi
