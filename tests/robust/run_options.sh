#!/usr/bin/env bash
# run_options.sh BIN_DIR SOURCE_DIR [sanitized] - every bad option value of every chapter exits 2
# with its one line, before any GL context; input files (and --screenshot's folder) are found from
# any folder.
#
# 1. Refused while parsing: each run has no GL at all (no EGL driver, OSMesa held below 3.3, as
#    robust.inputs does), so a value checked only after a context exists would exit 77, not 2.
#    Shared options on every chapter (--camera's bounds, --script, --scene) and each chapter's own.
# 2. With a context (skipped, 77, when there is none): the issue's `cd build/bin && 08 --scene
#    assets/scenes/city.scene`; chapter 13's --samples above the context's own limit (exit 2, the
#    same words); a framebuffer that does not fit in memory names GL_OUT_OF_MEMORY, and a --size
#    whose runner target alone cannot fit is refused before any target (exit 2; not under the
#    sanitizers, whose shadow memory a `ulimit -v` would starve).
set -u
bin_dir=$(cd "$1" && pwd) src=$(cd "$2" && pwd) sanitized=${3:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0

# expect CODE SUBSTRING BINARY ARGS...: no GL; exit CODE, one stderr line holding SUBSTRING.
expect() {
    local code=$1 want=$2 bin=$3
    shift 3
    (cd "$tmp" && env -u DISPLAY -u WAYLAND_DISPLAY __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent \
        MESA_GL_VERSION_OVERRIDE=3.2 "$bin_dir/$bin" --headless "$@") >"$tmp/out" 2>"$tmp/err"
    local rc=$? lines
    lines=$(grep -c . "$tmp/err")
    if [ "$rc" -ne "$code" ]; then
        fail=$((fail + 1)); echo "FAIL $bin $*: exit $rc, expected $code: $(head -2 "$tmp/err")"
    elif [ "$code" -eq 2 ] && { [ "$lines" -ne 1 ] || ! grep -qF -- "$want" "$tmp/err"; }; then
        fail=$((fail + 1)); echo "FAIL $bin $*: stderr ($lines lines) lacks '$want': $(head -2 "$tmp/err")"
    else
        pass=$((pass + 1)); echo "ok   $bin $* -> $rc"
    fi
}

mkdir "$tmp/folder"
printf '0 key M\n5 objects check\n' >"$tmp/nomark.script"
printf '0 key M\n1 screenshot nowhere/x.png\n' >"$tmp/noshotdir.script"
printf '0 screenshot x.gif\n' >"$tmp/gif.script"
chapters=$(cd "$bin_dir" && ls [0-1][0-9]_* 2>/dev/null)
[ -n "$chapters" ] || { echo "FAIL no chapter binaries in $bin_dir"; exit 1; }
for ch in $chapters; do
    expect 2 "far / near is 1e+60, more than a depth buffer can hold" "$ch" \
        --camera "eye 0 5 5 target 0 0 0 near 1e-30 far 1e30"
    expect 2 "camera fovy: must be at least 0.01 degrees, got '1e-30'" "$ch" --camera "eye 0 5 5 target 0 0 0 fovy 1e-30"
    expect 2 "cannot open script: not a regular file but a folder" "$ch" --script "$tmp/folder"
    expect 2 "objects check: no 'objects mark' before it" "$ch" --script "$tmp/nomark.script"
    expect 2 "(looked for $tmp/gone.scene and " "$ch" --scene gone.scene
    expect 2 "cannot write nowhere/x.png: No such file or directory (no folder nowhere: looked for $tmp/nowhere and " \
        "$ch" --screenshot nowhere/x.png
    expect 2 "noshotdir.script:2: screenshot: cannot write nowhere/x.png: No such file or directory (no folder nowhere: looked for $tmp/nowhere and " \
        "$ch" --script noshotdir.script
done
expect 2 "gif.script:1: screenshot: expected a file name ending in .png" 00_forward --script gif.script
expect 2 "bad --anisotropy '0': expected a whole number from 1 to 16" 16_visibility_buffer --anisotropy 0
expect 2 "bad --anisotropy '2.5': expected a whole number from 1 to 16" 18_pbr_materials --anisotropy 2.5
# Each chapter's own options.
expect 2 "bad --radius '0': expected a number from 1e-06 to 1000000" 04_light_volumes --radius 0
expect 2 "bad --radius 'big'" 04_light_volumes --radius big
expect 2 "bad --exposure '0'" 06_additive_blending --exposure 0
expect 2 "bad --tile-lights '0': expected a whole number from 1 to 1073741824" 10_tiled_deferred --tile-lights 0
expect 2 "bad --tile-lights '2.5'" 10_tiled_deferred --tile-lights 2.5
expect 2 "bad --tile '0': expected a whole number from 1 to 4096" 11_clustered --tile 0
expect 2 "bad --slices '513': expected a whole number from 1 to 512" 11_clustered --slices 513
expect 2 "bad --cluster-lights '0'" 11_clustered --cluster-lights 0
expect 2 "bad --samples '3': expected 1, 2, 4, 8, 16 or 32" 13_msaa --samples 3
expect 2 "bad --samples '2.5': expected 1, 2, 4, 8, 16 or 32" 13_msaa --samples 2.5
expect 2 "bad --samples '64'" 13_msaa --samples 64
expect 2 "bad --shadow-atlas '300': expected 256, 512, 1024" 14_shadows --shadow-atlas 300
expect 2 "bad --normal-offset '9': expected a number from 0 to 8" 14_shadows --normal-offset 9
expect 2 "bad --slope-bias 'x'" 14_shadows --slope-bias x
expect 2 "bad --shadows '2.5': expected a whole number" 14_shadows --shadows 2.5
expect 2 "bad --time-step '-1'" 14_shadows --time-step -1
expect 2 "bad --view-light '2.5': expected a whole number" 14_shadows --view-light 2.5
expect 2 "bad --ao-radius '0': expected a number from 0.001 to 1000" 17_ssao --ao-radius 0
expect 2 "bad --ao-samples '65': expected a whole number from 1 to 64" 17_ssao --ao-samples 65
expect 2 "bad --ao-blur '17'" 17_ssao --ao-blur 17
expect 2 "bad --probe-size '48'" 19_image_based_light --probe-size 48
expect 2 "bad --probe-size '8'" 19_image_based_light --probe-size 8
expect 2 "bad --ibl-samples '0': expected a whole number from 1 to 1024" 19_image_based_light --ibl-samples 0
# Each chapter's choices: a value that is none of them.
for pair in 04_light_volumes:scale 06_additive_blending:accum 06_additive_blending:tonemap \
            07_face_culling:cull 07_face_culling:depth-clamp 08_stencil_volumes:batch 08_stencil_volumes:count \
            08_stencil_volumes:depth-clamp 08_stencil_volumes:reset 09_spot_lights:spot-volume \
            09_spot_lights:scale 10_tiled_deferred:path 11_clustered:assign 12_transparency:sort \
            14_shadows:shadow-format 14_shadows:pcf 14_shadows:shadow-cull 15_light_prepass:specular 17_ssao:ssao 19_image_based_light:ibl; do
    expect 2 "unknown --${pair#*:} value 'bogus' (one of:" "${pair%%:*}" "--${pair#*:}" bogus
done
# Accepted by the parser: the run goes on to ask for a context, and finds none (77).
expect 77 "" 08_stencil_volumes --scene assets/scenes/city.scene
expect 77 "" 13_msaa --samples 8

# 2. With a context.
if ! env -u DISPLAY "$bin_dir/13_msaa" --headless --gl-info >"$tmp/info" 2>/dev/null; then
    echo "$pass passed, $fail failed (the checks with a context skipped: none here)"
    [ "$fail" -eq 0 ] && exit 77
    exit 1
fi
(cd "$bin_dir" && ./08_stencil_volumes --headless --scene assets/scenes/city.scene --size 64x48 \
    --screenshot "$tmp/city.png") >"$tmp/out" 2>"$tmp/err"
rc=$?
if [ "$rc" -eq 0 ] && [ -s "$tmp/city.png" ]; then pass=$((pass + 1)); echo "ok   cd bin && 08 --scene assets/scenes/city.scene"
else fail=$((fail + 1)); echo "FAIL cd bin && 08 --scene assets/scenes/city.scene: exit $rc: $(head -2 "$tmp/err")"; fi
# A script's screenshot in a folder of the current folder (where the run is, not beside the binary).
mkdir -p "$tmp/cwd/shots"
printf '0 screenshot shots/a.png\n' >"$tmp/cwd/shot.script"
(cd "$tmp/cwd" && env -u DISPLAY "$bin_dir/00_forward" --headless --size 32x24 --script shot.script) \
    >"$tmp/out" 2>"$tmp/err"
rc=$?
if [ "$rc" -eq 0 ] && [ -s "$tmp/cwd/shots/a.png" ]; then pass=$((pass + 1)); echo "ok   a script's screenshot shots/a.png lands in the current folder"
else fail=$((fail + 1)); echo "FAIL script screenshot shots/a.png: exit $rc: $(head -2 "$tmp/err")"; fi
env -u DISPLAY "$bin_dir/14_shadows" --headless --size 32x24 --view-light 8 >"$tmp/out" 2>"$tmp/err"
rc=$?
if [ "$rc" -eq 2 ] && grep -qF "bad --view-light '8': the scene has 8 lights (0 to 7)" "$tmp/err"; then
    pass=$((pass + 1)); echo "ok   14_shadows --view-light 8 on the default scene's 8 lights -> 2"
else fail=$((fail + 1)); echo "FAIL 14_shadows --view-light 8: exit $rc: $(head -2 "$tmp/err")"; fi
max=$(sed -n 's/.*max_samples=\([0-9]*\).*/\1/p' "$tmp/info")
over=$((max * 2))
if [ -n "$max" ] && [ "$over" -le 32 ]; then
    env -u DISPLAY "$bin_dir/13_msaa" --headless --size 32x24 --samples "$over" >"$tmp/out" 2>"$tmp/err"
    rc=$?
    if [ "$rc" -eq 2 ] && grep -qF "13_msaa: bad --samples '$over': this context allows at most $max" "$tmp/err"; then
        pass=$((pass + 1)); echo "ok   13_msaa --samples $over (the context allows $max) -> 2"
    else fail=$((fail + 1)); echo "FAIL 13_msaa --samples $over: exit $rc: $(head -2 "$tmp/err")"; fi
else
    echo "skip 13_msaa's context limit: this context allows $max samples, the parser's own bound 32"
fi
if [ "$sanitized" != sanitized ]; then
    # 1.5 GB of address space: a context, not an 8192x8192 G-buffer (~1 GB of targets and more).
    (ulimit -v 1500000; env -u DISPLAY "$bin_dir/03_fullscreen_phong" --headless --size 8192x8192) \
        >"$tmp/out" 2>"$tmp/err"
    rc=$?
    if [ "$rc" -eq 1 ] && grep -qF "because of GL_OUT_OF_MEMORY" "$tmp/err"; then
        pass=$((pass + 1)); echo "ok   an 8192x8192 G-buffer without the memory names GL_OUT_OF_MEMORY"
    else fail=$((fail + 1)); echo "FAIL 8192x8192 in 1.5 GB: exit $rc: $(head -3 "$tmp/err")"; fi
    # 16384x16384 is within llvmpipe's GL limits, but its runner's target alone (8 bytes a pixel,
    # 2 GiB) cannot fit in 1.5 GB: refused before any target is made, as a bad value (2), one line.
    if grep -q "renderer=.*llvmpipe" "$tmp/info"; then
        (ulimit -v 1500000; env -u DISPLAY "$bin_dir/03_fullscreen_phong" --headless --size 16384x16384) \
            >"$tmp/out" 2>"$tmp/err"
        rc=$?
        if [ "$rc" -eq 2 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] &&
                grep -qF -- "--size 16384x16384 needs at least 2048 MiB" "$tmp/err" &&
                grep -qF "(ulimit -v): try a smaller --size" "$tmp/err"; then
            pass=$((pass + 1)); echo "ok   16384x16384 in 1.5 GB -> 2 before any target is made"
        else fail=$((fail + 1)); echo "FAIL 16384x16384 in 1.5 GB: exit $rc: $(head -3 "$tmp/err")"; fi
    else
        echo "skip the memory estimate: not llvmpipe ($(grep renderer= "$tmp/info"))"
    fi
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
