#!/usr/bin/env bash
# build.sh [BUILD_DIR] [TARGET...] - install what is missing, configure and build (warnings are
# errors): every target, or only the TARGETs given (run-all.sh builds `course`: the chapters and
# the benchmark).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
targets=("${@:2}")
"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCOURSE_WERROR=ON >/dev/null
if [ ${#targets[@]} -gt 0 ]; then
  cmake --build "$build" -j"$(nproc)" --target "${targets[@]}"
else
  cmake --build "$build" -j"$(nproc)"
fi
