#!/usr/bin/env bash
# run_gltf_agreement.sh IMGDIFF OUTDIR SOURCE_DIR course|assimp TOLERANCE MAX_FRACTION BIN_A BIN_B
#
# Every scene of tests/gltf/samples.list from the chosen set (its header says the format), drawn at
# 320x240 by BIN_A and BIN_B (a forward and a deferred chapter), must agree: at most MAX_FRACTION of
# the pixels more than TOLERANCE levels apart. The pictures stay in OUTDIR/gltf_NAME.{a,b}.png, a
# heat map beside a failure. `assimp` exits 77 (skipped) when assimp-testmodels is not installed.
# Until the metallic-roughness shading lands, a model's material draws as its base colour through
# the Blinn-Phong path (specular 0): the agreement is what is checked, not the look.
set -u
if [ $# -ne 8 ]; then
    echo "usage: $0 IMGDIFF OUTDIR SOURCE_DIR course|assimp TOLERANCE MAX_FRACTION BIN_A BIN_B" >&2
    exit 2
fi
imgdiff=$1 outdir=$2 src=$(cd "$3" && pwd) set=$4 tol=$5 frac=$6 bin_a=$7 bin_b=$8
models=/usr/share/assimp/models
if [ "$set" = assimp ] && [ ! -d "$models/glTF2" ]; then
    echo "skip: assimp-testmodels is not installed ($models/glTF2; scripts/install-deps.sh installs it)"
    exit 77
fi
mkdir -p "$outdir"
pass=0 fail=0
while IFS= read -r line; do
    case $line in "#"* | "") continue ;; esac
    IFS='|' read -r name where args camera <<<"$line"
    name=$(echo $name) where=$(echo $where) args=$(echo $args) camera=$(echo $camera)
    case $where in
        course:*) [ "$set" = course ] || continue; path=$src/${where#course:} ;;
        assimp:*) [ "$set" = assimp ] || continue; path=$models/${where#assimp:} ;;
    esac
    scene=$outdir/gltf_$name.scene
    printf '%s\n' "camera $camera" "ambient 0.05 0.05 0.05" "model $path $args" \
        "light position 1.5 2 1.5 color 1 0.9 0.8 intensity 1.5" \
        "light position -2 1 1 color 0.4 0.6 1 intensity 1.2" \
        "light position 0.5 -1.5 2 color 1 0.5 0.3" >"$scene"
    why=""
    for side in a b; do
        bin=$bin_a
        [ $side = b ] && bin=$bin_b
        "$bin" --headless --size 320x240 --frames 1 --gl-debug --quiet --scene "$scene" \
            --screenshot "$outdir/gltf_$name.$side.png" >/dev/null 2>"$outdir/gltf_$name.$side.err"
        rc=$?
        [ $rc -eq 77 ] && { echo "skip: no GL context"; exit 77; }
        [ $rc -eq 0 ] || why="${bin##*/} exited with $rc: $(head -c 300 "$outdir/gltf_$name.$side.err")"
    done
    if [ -z "$why" ] && ! "$imgdiff" --tolerance "$tol" --max-fraction "$frac" \
            --heatmap-on-fail "$outdir/gltf_$name.diff.png" "$outdir/gltf_$name.a.png" \
            "$outdir/gltf_$name.b.png" >"$outdir/gltf_$name.diff" 2>&1; then
        why=$(cat "$outdir/gltf_$name.diff")
    fi
    if [ -z "$why" ]; then
        pass=$((pass + 1)); echo "ok   $name"
    else
        fail=$((fail + 1)); echo "FAIL $name: $why"
    fi
done <"$src/tests/gltf/samples.list"
echo "$pass passed, $fail failed"
[ "$pass" -gt 0 ] && [ "$fail" -eq 0 ]
