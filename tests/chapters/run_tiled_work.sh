#!/usr/bin/env bash
# run_tiled_work.sh BENCH CHAPTER_10 OUT_DIR - chapter 10's claim about work, as numbers. The work of
# tiled shading is its light-loop iterations ("evaluations"): every pixel with a surface loops over
# its tile's whole list. Checked:
#   1. the benchmark's deferred-tiled renderer evaluates at most 3x the ideal (pixel, light) pairs on
#      the default scene at 1024 generated lights (the issue's target) and on the city (1024 generated
#      lights and its own 757), and at least every ideal pair (ratio >= 0.999: a missed pair would be
#      a missing light). "Ideal" is counted exactly on the CPU from the depth buffer
#      (common/render/light_work.c: pairs whose surface point lies within the light's radius).
#   2. the chapter counts exactly what the benchmark counts (the chapter itself, run in-process), on
#      each path: the compute shader's lists, and the GL 3.3 path's (COURSE_NO_COMPUTE=1 makes the
#      benchmark take it); and both paths make the same lists (the same count).
#   3. --tile-lights 16 on that frame: the tiles with more lights loop over every light, so the
#      count grows (the picture does not: agree.10_tile_lights_16_same_picture).
# Exit 77 (no GL context) passes through as a skip.
set -u
. "$(dirname "$0")/../lib/args.sh"
args_expect 3 "$@"
. "$(dirname "$0")/work_lib.sh"
bench=$1 chapter=$2 out=$3
args_fresh_dir "$out"
work_bench "$bench" "$out/gpu" default,city 1024,scene deferred-volumes,deferred-tiled
COURSE_NO_COMPUTE=1 work_bench "$bench" "$out/cpu" default 1024 deferred-volumes,deferred-tiled

# CSV columns: 1 sweep, 2 scene, 3 renderer, 4 light_set, 5 lights, 17 shaded (here: evaluations),
# 19 ideal, 21 ratio.
awk -F, '
function fail(msg) { print "FAIL: " msg; bad = 1 }
NR == 1 { next }
$1 == "lights" && $3 == "deferred-tiled" {
    checked++
    printf "%-8s %5s lights (%s): tiled evaluates %s for %s ideal pairs = %s x\n", $2, $5, $4, $17, $19, $21
    if ($21 == "NA" || $21 > 3.0) fail($2 " " $5 " lights: ratio " $21 " > 3")
    if ($21 != "NA" && $21 < 0.999) fail($2 " " $5 " lights: ratio " $21 " < 1: pairs missed")
}
$1 == "lights" && $3 == "deferred-volumes" {
    printf "%-8s %5s lights (%s): chapter 07 shades %s = %s x\n", $2, $5, $4, $17, $21
}
END { if (checked != 4) fail(checked " tiled rows, want 4"); exit bad }' "$out/gpu/bench.csv" || exit 1

gpu_bench=$(work_csv "$out/gpu" default deferred-tiled 1024 17)
cpu_bench=$(work_csv "$out/cpu" default deferred-tiled 1024 17)
gpu=$(work_count "$chapter" --path compute) cpu=$(work_count "$chapter" --path cpu)
limited=$(work_count "$chapter" --tile-lights 16)
echo "default, 1024 lights: the chapter evaluates $gpu (compute path), $cpu (GL 3.3 path), $limited" \
    "(--tile-lights 16); the benchmark's renderer $gpu_bench (compute), $cpu_bench (COURSE_NO_COMPUTE=1)"
[ -n "$gpu" ] && [ "$gpu" = "$gpu_bench" ] || { echo "FAIL: compute path: chapter $gpu, benchmark $gpu_bench"; exit 1; }
[ -n "$cpu" ] && [ "$cpu" = "$cpu_bench" ] || { echo "FAIL: GL 3.3 path: chapter $cpu, benchmark $cpu_bench"; exit 1; }
[ "$gpu" = "$cpu" ] || { echo "FAIL: the two paths' lists differ: $gpu against $cpu evaluations"; exit 1; }
[ "$limited" -gt "$gpu" ] || { echo "FAIL: --tile-lights 16 evaluates $limited, not more than $gpu"; exit 1; }
echo "ok"
