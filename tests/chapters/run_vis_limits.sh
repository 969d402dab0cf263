#!/usr/bin/env bash
# run_vis_limits.sh CHAPTER OUT_DIR - chapter 16's id holds the object + 1 in 12 bits and the
# triangle in 20: a scene at each limit is drawn, one past it is refused when loaded (exit 2, one
# line that names the limit); the forward renderer, which has no ids, draws it. Exit 77 (no GL
# context) passes through as a skip.
set -u
bin=$1 out=$2
mkdir -p "$out"
# N cubes on a grid, or one sphere of SLICES x STACKS (2 * slices * (stacks - 1) triangles)
cubes() {
    printf 'camera eye 0 40 90 target 0 0 0\nmaterial m albedo 0.5 0.5 0.5\nmesh box cube\n'
    for ((i = 0; i < $1; i++)); do echo "object box m position $((i % 64 - 32)) 0 $((i / 64 - 32))"; done
}
sphere() { printf 'camera eye 0 0 4 target 0 0 0\nmaterial m albedo 0.5 0.5 0.5\nmesh ball sphere %s %s\nobject ball m\n' "$1" "$2"; }
expect() { # NAME RC PATTERN [ARGS...]: run on $out/NAME.scene
    "$bin" --headless --size 64x48 --frames 1 --gl-debug --scene "$out/$1.scene" "${@:4}" >"$out/$1.out" 2>"$out/$1.err"
    local rc=$?
    [ $rc -eq 77 ] && { echo "skip: no GL context"; exit 77; }
    cat "$out/$1.err"
    [ $rc -eq "$2" ] || { echo "FAIL: $1 exited $rc, expected $2"; exit 1; }
    [ -z "$3" ] || grep -q "$3" "$out/$1.err" || { echo "FAIL: $1: no line matching '$3'"; exit 1; }
}
cubes 4095 >"$out/objects_4095.scene"
cubes 4096 >"$out/objects_4096.scene"
sphere 1024 513 >"$out/triangles_2p20.scene"  # 1,048,576 triangles
sphere 1024 514 >"$out/triangles_over.scene"  # 1,050,624
expect objects_4095 0 ""
expect objects_4096 2 "4096 objects; the visibility buffer's ids hold at most 4095 (12 bits of object)"
expect objects_4096 0 "" --renderer forward  # no ids there: drawn
expect triangles_2p20 0 ""
expect triangles_over 2 "has 1050624 triangles; the visibility buffer's ids hold at most 1048576 a mesh (20 bits"
echo "ok: 4,095 objects and 2^20 triangles a mesh drawn, one more refused with exit 2"
