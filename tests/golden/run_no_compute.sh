#!/usr/bin/env bash
# run_no_compute.sh CHAPTER OUT_DIR OPTION - a chapter whose --OPTION chooses between compute shaders
# ("compute") and the GL 3.3 path ("cpu"): chapter 10's --path, chapter 11's --assign. On a context
# without compute shaders, simulated on a newer driver with COURSE_NO_COMPUTE=1 (common/gl/gl_util.c,
# gl_have_compute):
#   --OPTION compute fails: exit 1 and one line on stderr that says why and what to use instead;
#   no --OPTION takes the GL 3.3 path, and draws what --OPTION cpu draws (byte for byte).
# On a context that really lacks 4.3 the same happens without the variable (the message then says
# the context does not have them). Exit 77 (no GL context) passes through as a skip.
set -u
bin=$1 out=$2 option=$3
mkdir -p "$out"
COURSE_NO_COMPUTE=1 "$bin" --headless --size 64x48 --frames 1 --$option compute >"$out/nc.out" 2>"$out/nc.err"
rc=$?
[ $rc -eq 77 ] && { echo "skip: no GL context"; exit 77; }
cat "$out/nc.err"
[ $rc -eq 1 ] || { echo "FAIL: --$option compute without compute shaders exited $rc, expected 1"; exit 1; }
[ "$(grep -c . "$out/nc.err")" -eq 1 ] || { echo "FAIL: expected one line on stderr"; exit 1; }
grep -q -- "--$option compute needs compute shaders (OpenGL 4.3).*use --$option cpu" "$out/nc.err" ||
    { echo "FAIL: the line does not say what is missing and what to use"; exit 1; }
COURSE_NO_COMPUTE=1 "$bin" --headless --size 64x48 --frames 1 --gl-debug --screenshot "$out/auto.png" 2>"$out/auto.err" ||
    { echo "FAIL: with no --$option it did not fall back to the GL 3.3 path"; cat "$out/auto.err"; exit 1; }
"$bin" --headless --size 64x48 --frames 1 --gl-debug --$option cpu --screenshot "$out/cpu.png" 2>/dev/null ||
    { echo "FAIL: --$option cpu"; exit 1; }
cmp -s "$out/auto.png" "$out/cpu.png" || { echo "FAIL: the fallback drew another picture than --$option cpu"; exit 1; }
echo "ok: --$option compute refused, the default fell back to the GL 3.3 path"
