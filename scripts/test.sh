#!/usr/bin/env bash
# test.sh - install what is missing, build, and run the whole test suite (ctest); then build the
# sanitizer tree (build-asan, as preset asan) and run its unit tests and one headless frame of every
# chapter under AddressSanitizer, LeakSanitizer and UndefinedBehaviorSanitizer.
# Tests that cannot get a GL context are reported as skipped, never as passed.
# Arguments go to the first ctest; COURSE_TEST_ASAN=0 leaves out the sanitizer tree.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh" "$root/build"
status=0
ctest --test-dir "$root/build" --output-on-failure -j"$(nproc)" "$@" || status=$?

if [ "${COURSE_TEST_ASAN:-1}" != 0 ]; then
  asan=$root/build-asan
  cmake -S "$root" -B "$asan" -DCMAKE_BUILD_TYPE=Debug -DCOURSE_WERROR=ON -DCOURSE_SANITIZE=ON >/dev/null
  cmake --build "$asan" -j"$(nproc)"
  LSAN_OPTIONS="suppressions=$root/tests/robust/lsan.supp" \
    ctest --test-dir "$asan" --output-on-failure -j"$(nproc)" -L 'unit|sanitize' || status=$?
fi
exit "$status"
