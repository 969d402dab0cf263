#!/usr/bin/env bash
# test.sh - install what is missing, build, and run the whole test suite (ctest).
# Tests that cannot get a GL context are reported as skipped, never as passed.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh" "$root/build"
ctest --test-dir "$root/build" --output-on-failure -j"$(nproc)" "$@"
