#!/usr/bin/env bash
# build.sh [BUILD_DIR] - install what is missing, configure and build (warnings are errors).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCOURSE_WERROR=ON >/dev/null
cmake --build "$build" -j"$(nproc)"
