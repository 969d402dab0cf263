#!/usr/bin/env bash
# run_compute_key.sh CHAPTER OUT_DIR OPTION WHAT - the L key of a chapter whose --OPTION chooses
# between compute shaders and the GL 3.3 path (chapter 10's --path, chapter 11's --assign), driven
# by a --script headless:
#   from --OPTION compute, L switches to the CPU (one log line "WHAT: the CPU") and the frame after
#   it is what --OPTION cpu draws, byte for byte; L again switches back, and the frame is compute's;
#   on a context without compute shaders (COURSE_NO_COMPUTE=1) L logs one line and stays.
# Exit 77 (no GL context) passes through as a skip.
set -u
. "$(dirname "$0")/../lib/args.sh"
bin=$1 out=$2 option=$3 what=$4
args_fresh_dir "$out"
mkdir -p "$out"
printf '1 key L\n1 screenshot %s\n2 key L\n2 screenshot %s\n' "$out/key.png" "$out/back.png" >"$out/key.script"
"$bin" --headless --size 96x64 --gl-debug --$option compute --script "$out/key.script" >"$out/key.log" 2>&1
rc=$?
[ $rc -eq 77 ] && { echo "skip: no GL context"; exit 77; }
[ $rc -eq 0 ] || { echo "FAIL: the run with the L key exited $rc"; cat "$out/key.log"; exit 1; }
[ "$(grep -- "^$what: " "$out/key.log" | tr '\n' '/')" = "$what: the CPU/$what: compute shaders/" ] ||
    { echo "FAIL: expected the lines '$what: the CPU', '$what: compute shaders'"; cat "$out/key.log"; exit 1; }
"$bin" --headless --size 96x64 --gl-debug --$option cpu --frames 2 --screenshot "$out/cpu.png" >/dev/null 2>&1 ||
    { echo "FAIL: --$option cpu"; exit 1; }
cmp -s "$out/key.png" "$out/cpu.png" || { echo "FAIL: after L the picture is not --$option cpu's"; exit 1; }
"$bin" --headless --size 96x64 --gl-debug --$option compute --frames 3 --screenshot "$out/compute.png" >/dev/null 2>&1 ||
    { echo "FAIL: --$option compute"; exit 1; }
cmp -s "$out/back.png" "$out/compute.png" || { echo "FAIL: after L twice the picture is not compute's"; exit 1; }
printf '1 key L\n' >"$out/nc.script"
COURSE_NO_COMPUTE=1 "$bin" --headless --size 96x64 --script "$out/nc.script" >"$out/nc.log" 2>&1 ||
    { echo "FAIL: L without compute shaders"; cat "$out/nc.log"; exit 1; }
[ "$(grep -c -- "^$what: " "$out/nc.log")" -eq 1 ] &&
    grep -q -- "^$what: still the CPU, this context has no compute shaders" "$out/nc.log" ||
    { echo "FAIL: without compute shaders L should log one line and stay"; cat "$out/nc.log"; exit 1; }
echo "ok: L switched $what to the CPU and back (same pictures), and stayed without compute shaders"
