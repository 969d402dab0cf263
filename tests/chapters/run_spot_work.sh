#!/usr/bin/env bash
# run_spot_work.sh CHAPTER_09 CHAPTER_07 SCENE - chapter 09's claim about work, as numbers: on the
# spots scene its cones shade fewer lighting fragments (--bench's shaded_pixels, GL_SAMPLES_PASSED)
# than its spheres (--spot-volume sphere), and as spheres it shades exactly what chapter 07 shades.
# Exit 77 (no GL context) passes through as a skip.
set -u
ch09=$1 ch07=$2 scene=$3
shaded() { # BINARY ARGS...
    local out rc
    out=$("$@" --headless --size 800x600 --frames 1 --scene "$scene" --bench 2>&1)
    rc=$?
    [ $rc -eq 77 ] && { echo "skip: no GL context"; exit 77; }
    [ $rc -ne 0 ] && { echo "FAIL: $* exited $rc"; echo "$out"; exit 1; }
    sed -n 's/.*shaded_pixels=\([0-9-]*\).*/\1/p' <<<"$out"
}
cones=$(shaded "$ch09") || exit $?
spheres=$(shaded "$ch09" --spot-volume sphere) || exit $?
chapter07=$(shaded "$ch07") || exit $?
echo "spots scene, 800x600: shaded $cones with cones, $spheres with spheres, chapter 07 $chapter07"
[ -n "$cones" ] && [ -n "$spheres" ] && [ -n "$chapter07" ] || { echo "FAIL: no shaded_pixels"; exit 1; }
[ "$spheres" = "$chapter07" ] || { echo "FAIL: as spheres the chapter shades $spheres, chapter 07 $chapter07"; exit 1; }
[ "$cones" -lt "$spheres" ] || { echo "FAIL: the cones shade $cones, not fewer than the spheres' $spheres"; exit 1; }
echo "ok: the cones shade $(awk -v c="$cones" -v s="$spheres" 'BEGIN { printf "%.1f %%", 100 * c / s }') of the spheres' fragments"
