#!/usr/bin/env bash
# run_install.sh BUILD_DIR: the programs find their shaders and scenes wherever they run from: the
# build tree's binaries from another folder, and an installed, then moved, prefix on its own.
set -u
build=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
check() { # WHAT EXPECTED_ORIGIN -- COMMAND...
  local what=$1 origin=$2
  shift 3
  (cd "$tmp" && env -u COURSE_DATA_DIR -u COURSE_SHADER_DIR "$@" --headless --size 64x48 --verbose \
    --screenshot "$tmp/shot.png") >"$tmp/out" 2>&1
  local rc=$?
  if [ $rc -eq 77 ]; then echo "skip: no GL context"; exit 77; fi
  if [ $rc -ne 0 ] || [ ! -s "$tmp/shot.png" ]; then
    echo "FAIL $what: exit $rc"; tail -3 "$tmp/out"; fail=1
  elif ! grep -q "(from $origin)" "$tmp/out"; then
    echo "FAIL $what: data not from $origin: $(grep 'data folder' "$tmp/out")"; fail=1
  else
    echo "ok   $what: $(grep -o 'data folder .*' "$tmp/out")"
  fi
  rm -f "$tmp/shot.png"
}
check "build tree, run from elsewhere" "the source tree" -- "$build/bin/07_face_culling"
cmake --install "$build" --prefix "$tmp/prefix" >"$tmp/install.log" 2>&1 ||
  { echo "FAIL cmake --install"; tail -3 "$tmp/install.log"; exit 1; }
mv "$tmp/prefix" "$tmp/moved"
check "installed prefix, moved" "the installed prefix" -- "$tmp/moved/bin/07_face_culling"
check "--data-dir" "--data-dir" -- "$tmp/moved/bin/03_fullscreen_phong" --data-dir "$tmp/moved/share/deferred_course"
exit $fail
