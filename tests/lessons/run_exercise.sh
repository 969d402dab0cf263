#!/usr/bin/env bash
# run_exercise.sh BIN_DIR SOURCE_DIR OUT_DIR EXERCISE - one page exercise performed as its text says
# (EXERCISE: 00.2 is docs/00_*.md's exercise 2): the runs it names, and each target it states checked
# twice, in the page's words (so the page cannot drift) and in what the run printed or drew; or one of
# a page's measured tables (EXERCISE: 03.exactness, 06.exactness), measured again.
# Exit 0 when every target is met, 1 when one is not, 77 without a GL context.
set -u
source "$(dirname "$0")/../lib/args.sh"
args_expect 4 "$@"
bin=$1 src=$(cd "$2" && pwd) out=$3 exercise=$4
args_fresh_dir "$out"
out=$(cd "$out" && pwd)
page=$(ls "$src"/docs/"${exercise%%.*}"_*.md 2>/dev/null | head -n 1)
[ -n "$page" ] || { echo "FAIL: no page docs/${exercise%%.*}_*.md"; exit 1; }
A=$src/assets/scenes
fail=0

# The page's text on one line, spaces collapsed: a target may be wrapped anywhere.
text=$(tr '\n' ' ' <"$page" | tr -s ' ')
said() { # PHRASE: the page states it
    if grep -qF -- "$1" <<<"$text"; then echo "ok   the page says: $1"; else echo "FAIL the page no longer says: $1"; fail=1; fi
}
run() { # NAME CHAPTER ARGS...: the chapter's output in OUT_DIR/NAME.log
    local name=$1 chapter=$2
    shift 2
    local exe=$bin/$chapter
    [ -x "$out/bin/$chapter" ] && exe=$out/bin/$chapter # a chapter patched by patched_chapter
    (cd "$src" && "$exe" "$@") >"$out/$name.log" 2>&1
    local rc=$?
    [ "$rc" -eq 77 ] && { echo "skip: no GL context"; exit 77; }
    [ "$rc" -eq 0 ] || { echo "FAIL: $chapter $* exited $rc"; cat "$out/$name.log"; exit 1; }
}
printed() { # NAME TEXT: the run NAME printed TEXT
    if grep -qF -- "$2" "$out/$1.log"; then echo "ok   $1 printed: $2"; else
        echo "FAIL $1 did not print: $2"; grep -E "bench:|debug:|msaa:|shadows:" "$out/$1.log" | head -n 5; fail=1; fi
}
over() { # A.png B.png: imgdiff's count of pixels beyond 1/255
    "$bin/imgdiff" "$1" "$2" 2>&1 | tee -a "$out/imgdiff.log" | sed -n 's/.*over_tol=\([0-9]*\).*/\1/p'
}
equal() { # WHAT GOT WANT
    if [ "$2" = "$3" ]; then echo "ok   $1: $2"; else echo "FAIL $1: $2, the page says $3"; fail=1; fi
}
# A count of pixels beyond a tolerance moves with llvmpipe's last bits, which differ between CPUs:
# within 1 % of the page's figure (and 1 pixel), as tests/chapters/run_pbr_exercise.sh allows.
near() { # WHAT GOT WANT
    if [ -n "$2" ] && awk "BEGIN { d = $2 - $3; e = $3 / 100; exit !(d * d <= (e > 1 ? e : 1) ^ 2) }"; then
        echo "ok   $1: $2 (the page: $3)"; else echo "FAIL $1: $2, the page says $3"; fail=1; fi
}
bench=(--headless --frames 1 --warmup 0 --bench)

# An exercise that changes a shader, performed on a copy: the shaders a chapter would read
# (COURSE_DATA_DIR's, else the course's) copied to OUT_DIR/data/shaders, the assets linked beside them,
# so that --data-dir OUT_DIR/data (or COURSE_SHADER_DIR=OUT_DIR/data/shaders) runs on the copy.
shader_copy() {
    local data=${COURSE_DATA_DIR:-$src}
    mkdir -p "$out/data" && cp -r "$data/shaders" "$out/data/shaders" && ln -s "$data/assets" "$out/data/assets" ||
        exit 1
}

# An exercise that changes a chapter's C code, performed on a copy: the one source copied, patched
# with sed, compiled with the flags CMake gave the chapter and linked with its link line, its own
# object replaced (the libraries are the ones already built). The binary is OUT_DIR/bin/NAME, which
# run NAME then starts in place of BIN_DIR/CHAPTER.
# A header the chapter includes may be patched the same way (HEADER: its path in the course, found
# first on the include path); only the chapter sees the change, not the libraries built before it.
patched_chapter() { # NAME CHAPTER 'FIXED TEXT' SED_SCRIPT [HEADER HEADER_SED_SCRIPT]: the text must be there
    local name=$1 chapter=$2 header=${5:-} header_script=${6:-} first=""
    patched_copy "$name" "chapters/$chapter.c" "$3" "$4" "$header" || exit 1
    if [ -n "$header" ]; then
        first=$out/patched/$name.include
        mkdir -p "$first" && cp "$src/$header" "$first/" || exit 1
        sed -i "$header_script" "$first/${header##*/}"
        if cmp -s "$src/$header" "$first/${header##*/}"; then echo "FAIL: the patch changed nothing in $header"; exit 1; fi
        diff -u "$src/$header" "$first/${header##*/}" | sed -n '3,$p' | sed 's/^/     /'
        first="-I$first"
    fi
    patched_build "$name" "$chapter" "CMakeFiles/$chapter.dir/flags.make" "$first" replace
    echo "ok   built $chapter with the patch as $name"
}

# The same for a module of common/ a chapter links (SOURCE: its path, common/gl/gpu_scene.c): the copy
# compiled with the flags CMake gave the common library, its object put on the chapter's link line
# before the libraries, so it stands in for theirs. The binary is OUT_DIR/bin/NAME.
patched_common() { # NAME CHAPTER SOURCE 'FIXED TEXT' SED_SCRIPT
    local name=$1 chapter=$2 source=$3
    patched_copy "$name" "$source" "$4" "$5" "" || exit 1
    patched_build "$name" "$chapter" CMakeFiles/common.dir/flags.make "" add
    echo "ok   built $chapter with the patched $source as $name"
}

# OUT_DIR/patched/NAME.c: the course's SOURCE with SED_SCRIPT applied, which must change it (unless a
# header is patched instead) and find FIXED TEXT first; the change printed.
patched_copy() { # NAME SOURCE 'FIXED TEXT' SED_SCRIPT HEADER
    local copy=$out/patched/$1.c
    mkdir -p "$out/bin" "$out/patched"
    cp "$src/$2" "$copy" || return 1
    grep -qF -- "$3" "$copy" || { echo "FAIL: $2 no longer has: $3"; return 1; }
    sed -i "$4" "$copy"
    if [ -z "$5" ] && cmp -s "$src/$2" "$copy"; then echo "FAIL: the patch changed nothing"; return 1; fi
    diff -u "$src/$2" "$copy" | sed -n '3,$p' | sed 's/^/     /'
}

# OUT_DIR/patched/NAME.c compiled with FLAGS_FILE's flags (and INCLUDE first), then CHAPTER's link line
# with that object replacing the chapter's own (replace) or beside it, before the libraries (add).
patched_build() { # NAME CHAPTER FLAGS_FILE INCLUDE replace|add
    local name=$1 chapter=$2 flags=$3 first=$4 build=$bin/.. dir=CMakeFiles/$2.dir
    [ -f "$build/$flags" ] && [ -f "$build/$dir/link.txt" ] || { echo "FAIL: no $flags or $dir/link.txt under $build"; exit 1; }
    local cc defines includes cflags object=$dir/chapters/$chapter.c.o link
    cc=$(sed -n 's/^# compile C with //p' "$build/$flags")
    defines=$(sed -n 's/^C_DEFINES = //p' "$build/$flags")
    includes=$(sed -n 's/^C_INCLUDES = //p' "$build/$flags")
    cflags=$(sed -n 's/^C_FLAGS = //p' "$build/$flags")
    # shellcheck disable=SC2086 # the flags are CMake's words, one per option
    (cd "$build" && "${cc:-cc}" $defines $first $includes $cflags -c "$out/patched/$name.c" -o "$out/patched/$name.o") ||
        { echo "FAIL: the patched copy $name.c does not compile"; exit 1; }
    local with="$out/patched/$name.o"
    [ "$5" = add ] && with="$object $out/patched/$name.o"
    link=$(sed -e "s| $object | $with |" -e "s| -o bin/$chapter | -o $out/bin/$name |" "$build/$dir/link.txt")
    case $link in *"$out/patched/$name.o"*"$out/bin/$name"*) ;;
        *) echo "FAIL: $dir/link.txt does not name chapters/$chapter.c.o and bin/$chapter"; exit 1 ;; esac
    (cd "$build" && eval "$link") || { echo "FAIL: $chapter with the patched copy $name.c does not link"; exit 1; }
}

case $exercise in
00.2) # shaded_pixels with and without the pre-pass, whatever the light count
    said "301,770 without the pre-pass and 269,569 with it at every light count"
    said "1 − 269,569 / 301,770 = 10.7 %"
    for lights in 1 16 256; do
        run "naive_$lights" 00_forward "${bench[@]}" --size 800x600 --renderer forward-naive --lights "$lights"
        printed "naive_$lights" "shaded_pixels=301770 "
        run "prepass_$lights" 00_forward "${bench[@]}" --size 800x600 --renderer forward-prepass --lights "$lights"
        printed "prepass_$lights" "shaded_pixels=269569 "
    done ;;
00.3) # the lists' size, logged by --verbose
    said "on the default scene 356 (object, light) pairs for 7 objects, 50.9 lights per object instead of 256"
    said "14,789 pairs for 2,491 objects, 5.9 per object"
    lists=(--headless --size 160x120 --frames 1 --renderer forward-lists --lights 256 --seed 7 --verbose)
    run default 00_forward "${lists[@]}" --screenshot "$out/default.png"
    printed default "light lists: 356 (object, light) pairs for 7 objects and 256 lights: 50.9 lights per object"
    run city 00_forward "${lists[@]}" --scene "$A/city.scene" --screenshot "$out/city.png"
    printed city "light lists: 14789 (object, light) pairs for 2491 objects and 256 lights: 5.9 lights per object"
    ;;
02.4) # chapter 07 on the city with the 24-bit depth and with the default, against chapter 00
    said "63 pixels beyond 1/255 with the default (within the 0.01 % bound), 70 with \`compact-d24s8\` (over it), and 78 between"
    city=(--headless --size 800x800 --frames 1 --scene "$A/city.scene")
    run forward 00_forward "${city[@]}" --screenshot "$out/forward.png"
    run default 07_face_culling "${city[@]}" --screenshot "$out/default.png"
    run d24s8 07_face_culling "${city[@]}" --gbuffer compact-d24s8 --screenshot "$out/d24s8.png"
    near "the default against chapter 00, pixels beyond 1/255" "$(over "$out/forward.png" "$out/default.png")" 63
    near "compact-d24s8 against chapter 00" "$(over "$out/forward.png" "$out/d24s8.png")" 70
    near "the two layouts" "$(over "$out/default.png" "$out/d24s8.png")" 78 ;;
02.3) # the reference layout's normal at full float precision: 1/255 here and there (on a copy of the shaders)
    said "203 pixels move, each by 1/255"
    said "against chapter 00 no pixel is beyond 1/255 either way (max 1 before and after"
    shader_copy
    frag=$out/data/shaders/gbuffer.frag
    grep -q 'vec4(octahedral_encode_half(n), specular' "$frag" || { echo "FAIL: gbuffer.frag has no octahedral_encode_half to replace"; exit 1; }
    sed -i 's/vec4(octahedral_encode_half(n), specular/vec4(octahedral_encode(n), specular/' "$frag"
    small=(--headless --size 320x240 --frames 1)
    run forward 00_forward "${small[@]}" --screenshot "$out/forward.png"
    run half 03_fullscreen_phong "${small[@]}" --gbuffer reference --screenshot "$out/half.png"
    run float 03_fullscreen_phong "${small[@]}" --gbuffer reference --data-dir "$out/data" --screenshot "$out/float.png"
    near "pixels beyond 0/255 between the two" \
        "$("$bin/imgdiff" --tolerance 0 "$out/half.png" "$out/float.png" 2>&1 | sed -n 's/.*over_tol=\([0-9]*\) .*/\1/p')" 203
    for p in half float; do
        equal "$p against chapter 00, pixels beyond 1/255" "$(over "$out/forward.png" "$out/$p.png")" 0
        equal "$p against chapter 00, max" "$("$bin/imgdiff" "$out/forward.png" "$out/$p.png" 2>&1 |
            sed -n 's/.*max=\([0-9]*\) .*/\1/p')" 1
    done ;;
04.1) # the lighting fragments at radius 2, 3 and 8 (the pictures: golden.04_light_volumes_radius2, _radius8)
    said "34,518 at radius 2, 76,988 at the default 3, 326,385 at 8"
    for r in 2:34518 3:76988 8:326385; do
        run "radius_${r%:*}" 04_light_volumes "${bench[@]}" --size 320x240 --radius "${r%:*}"
        printed "radius_${r%:*}" "shaded_pixels=${r#*:} "
    done ;;
05.1) # the violet light drawn first: the page's own command makes the copy
    said "40,630 pixels (52.9 %) differ beyond 1/255, by up to 176/255"
    command=$(grep -o "(grep 'color 0.8 0.2 1.0'[^\`]*" "$page" | head -n 1)
    [ -n "$command" ] || { echo "FAIL: exercise 1 no longer gives its copy's command"; exit 1; }
    (cd "$src" && eval "${command/violet_first.scene/$out/violet_first.scene}") || { echo "FAIL: $command"; exit 1; }
    [ "$(grep -n 'color 0.8 0.2 1.0' "$out/violet_first.scene" | cut -d: -f1)" = 1 ] || { echo "FAIL: the violet light is not first"; exit 1; }
    run violet 05_attenuation_radius --headless --size 320x240 --frames 1 --scene "$out/violet_first.scene" \
        --screenshot "$out/violet.png"
    near "pixels beyond 1/255" "$(over "$src/tests/golden/05_attenuation_radius.png" "$out/violet.png")" 40630
    grep -q "max=176 " "$out/imgdiff.log" && echo "ok   by up to 176/255" || { echo "FAIL: not by up to 176/255"; fail=1; } ;;
05.2) # the textbook root in light_radius (a copy of common/scene/light.c): the default scene's ring unchanged
    said "is still \`tests/golden/05_attenuation_radius_ring.png\` to the byte, and \`--verbose\` logs the same radii"
    said "keeps r = 50.2 down to Kq = 1e-15 (50.1821), is 0.5 % short at 1e-16 (49.96) and 11.5 % at 1e-17 (44.4089)"
    patched_common textbook 05_attenuation_radius common/scene/light.c "    c_e += p_e - k_e;" \
        '/^    c_e += p_e - k_e;$/a\    if (kq != 0.0) /* the textbook root */\n        return (-kl + sqrt(kl * kl + 4.0 * kq * ldexp(c_m, c_e))) / (2.0 * kq);'
    run ring textbook --headless --size 320x240 --frames 1 --view ring --verbose --screenshot "$out/ring.png"
    equal "the ring's pixels beyond 0/255 against its golden" \
        "$("$bin/imgdiff" --tolerance 0 "$src/tests/golden/05_attenuation_radius_ring.png" "$out/ring.png" 2>&1 |
           sed -n 's/.*over_tol=\([0-9]*\) .*/\1/p')" 0
    run ring_kept 05_attenuation_radius --headless --size 64x48 --frames 1 --verbose
    equal "the default scene's radii logged" "$(grep -c -- '-> radius' "$out/ring.log")" 8
    equal "radii that differ from the chapter's" \
        "$(diff <(grep -- '-> radius' "$out/ring.log") <(grep -- '-> radius' "$out/ring_kept.log") | grep -c '^<')" 0
    # one light of Kc = 1, Kl = 1, peak 1 added to the default scene's frame: the radius each logs
    for row in 1e-15:50.2:50.1821 1e-16:50.2:49.96 1e-17:50.2:44.4089; do
        IFS=: read -r kq conjugate textbook <<<"$row"
        sed -n '/^light /q;p' "$A/default.scene" >"$out/kq_$kq.scene"
        echo "light position 0 2 0 color 1 1 1 intensity 1 attenuation 1 1 $kq" >>"$out/kq_$kq.scene"
        run "conjugate_$kq" 05_attenuation_radius --headless --size 64x48 --frames 1 --verbose --scene "$out/kq_$kq.scene"
        printed "conjugate_$kq" "light 0: kc 1 kl 1 kq $kq intensity 1 -> radius $conjugate"
        run "textbook_$kq" textbook --headless --size 64x48 --frames 1 --verbose --scene "$out/kq_$kq.scene"
        printed "textbook_$kq" "light 0: kc 1 kl 1 kq $kq intensity 1 -> radius $textbook"
    done ;;
05.3) # light 4's radius either side of the camera's distance
    said "camera (distance 6.31)"
    said "between 0.0482 (\`--cutoff 0.0482 --verbose\` logs light 4's radius as 6.31327) and 0.0484 (6.29874"
    for c in 0.0482:6.31327 0.0484:6.29874; do
        run "cutoff_${c%:*}" 05_attenuation_radius --headless --size 64x48 --frames 1 --verbose --cutoff "${c%:*}" \
            --screenshot "$out/cutoff_${c%:*}.png"
        printed "cutoff_${c%:*}" "light 4: kc 1 kl 0.35 kq 0.44 intensity 1 -> radius ${c#*:}"
    done
    # the camera's distance to light 4, from the scene
    d=$(awk '$1 == "camera" { ex = $3; ey = $4; ez = $5 } $1 == "light" { if (n++ == 4) { lx = $3; ly = $4; lz = $5 } }
        END { printf "%.2f", sqrt((ex - lx) ^ 2 + (ey - ly) ^ 2 + (ez - lz) ^ 2) }' "$A/default.scene")
    equal "the camera's distance to light 4" "$d" 6.31 ;;
08.4) # the draws with batches and without, and the batch counts of "The batches" (one frame each, --verbose)
    said "\`stencil: 120 batches for 1024 lights (0 full-screen): 241 draws\` with batches"
    said "\`stencil: 1024 batches for 1024 lights (0 full-screen): 2049 draws\` with \`--batch off\`"
    said "42 batches for 64 lights, 69 for 256, 120 for 1,024 (241 draws instead of 2,049, the ambient's included), 327 for 4,096; 65 for the city's 757"
    once=(--headless --size 800x800 --frames 1 --verbose)
    for n in 64:42:85 256:69:139 1024:120:241 4096:327:655; do
        IFS=: read -r lights batches draws <<<"$n"
        run "lights_$lights" 08_stencil_volumes "${once[@]}" --lights "$lights"
        printed "lights_$lights" "stencil: $batches batches for $lights lights (0 full-screen): $draws draws"
    done
    run batch_off 08_stencil_volumes "${once[@]}" --lights 1024 --batch off
    printed batch_off "stencil: 1024 batches for 1024 lights (0 full-screen): 2049 draws"
    run city 08_stencil_volumes "${once[@]}" --scene "$A/city.scene"
    printed city "stencil: 65 batches for 757 lights (0 full-screen): 131 draws" ;;
10.6) # the two paths on the city: the same evaluations, different passes
    said "both print \`shaded_pixels=8450764\`"
    for path in compute:tile_culling_ms cpu:tile_depth_bounds_ms; do
        run "${path%:*}" 10_tiled_deferred "${bench[@]}" --size 800x800 --scene "$A/city.scene" --path "${path%:*}"
        printed "${path%:*}" "shaded_pixels=8450764 "
        printed "${path%:*}" " ${path#*:}="
    done
    printed cpu " light_culling_ms=" ;;
11.1) # the light evaluations with the default slices and with 24
    said "275,725 light evaluations with the default slices and 424,762 with 24"
    for s in default:275725 24:424762; do
        slices=()
        [ "${s%:*}" = default ] || slices=(--slices "${s%:*}")
        run "slices_${s%:*}" 11_clustered "${bench[@]}" --size 320x240 --lights 256 "${slices[@]}"
        printed "slices_${s%:*}" "shaded_pixels=${s#*:} "
    done ;;
13.6) # the msaa: lines' bytes per pixel at 4 samples
    said "both print \`bytes_per_pixel=48\` with the default \`compact\` layout"
    said "with \`--gbuffer reference\` the deferred line says 64 and forward's stays 48"
    run deferred 13_msaa "${bench[@]}" --size 160x120
    printed deferred "msaa: renderer=deferred samples=4 bytes_per_sample=12 bytes_per_pixel=48 "
    run forward 13_msaa "${bench[@]}" --size 160x120 --renderer forward
    printed forward "msaa: renderer=forward samples=4 bytes_per_sample=12 bytes_per_pixel=48 "
    run deferred_reference 13_msaa "${bench[@]}" --size 160x120 --gbuffer reference
    printed deferred_reference "msaa: renderer=deferred samples=4 bytes_per_sample=16 bytes_per_pixel=64 "
    run forward_reference 13_msaa "${bench[@]}" --size 160x120 --gbuffer reference --renderer forward
    printed forward_reference "msaa: renderer=forward samples=4 bytes_per_sample=12 bytes_per_pixel=48 " ;;
14.3) # the teapots in a small atlas, and with 8 shadows
    said "\`dropped=70\` and \`tier_lights=0/0/0/10\`"
    said "\`not_chosen=72\` and \`tier_lights=0/8/0/0\`"
    teapots=("${bench[@]}" --size 160x120 --scene "$A/teapots.scene")
    run atlas1024 14_shadows "${teapots[@]}" --shadow-atlas 1024
    printed atlas1024 "shadowed=10 off=0 not_chosen=0 dropped=70 tier_lights=0/0/0/10 tiles=60 "
    run shadows8 14_shadows "${teapots[@]}" --shadows 8
    printed shadows8 "shadowed=8 off=0 not_chosen=72 dropped=0 tier_lights=0/8/0/0 " ;;
14.4) # the shadow pass's triangles with culling and without
    said "26001248 with culling, 140821440 without"
    teapots=("${bench[@]}" --size 160x120 --scene "$A/teapots.scene")
    run cull_on 14_shadows "${teapots[@]}"
    printed cull_on "cull=on "
    printed cull_on " triangles=26001248 "
    run cull_off 14_shadows "${teapots[@]}" --shadow-cull off
    printed cull_off "cull=off "
    printed cull_off " triangles=140821440 " ;;
16.4) # the maps' gradients set to zero: level 0 everywhere (on a copy of the shaders)
    said "42 pixels beyond 1/255 against forward (up to 13/255) before, 20,587 (26.8 %) after, up to 211/255"
    shader_copy
    frag=$out/data/shaders/visibility_shade.frag
    [ "$(grep -cE '^        g_map_d[xy] = uvs \* \(w[xy] - wc\);$' "$frag")" = 2 ] ||
        { echo "FAIL: visibility_shade.frag does not set g_map_dx and g_map_dy as the page says"; exit 1; }
    sed -i -E 's/^        (g_map_d[xy]) = uvs \* \(w[xy] - wc\);$/        \1 = vec2(0.0);/' "$frag"
    teapots=(--headless --size 320x240 --frames 1 --scene "$A/pbr_teapots.scene" --anisotropy 1)
    run forward 00_forward "${teapots[@]}" --screenshot "$out/forward.png"
    run kept 16_visibility_buffer "${teapots[@]}" --screenshot "$out/kept.png"
    run zero 16_visibility_buffer "${teapots[@]}" --data-dir "$out/data" --screenshot "$out/zero.png"
    for pw in kept:42:13 zero:20587:211; do
        IFS=: read -r p pixels max <<<"$pw"
        near "$p against forward, pixels beyond 1/255" "$(over "$out/forward.png" "$out/$p.png")" "$pixels"
        near "$p against forward, max" "$("$bin/imgdiff" "$out/forward.png" "$out/$p.png" 2>&1 |
            sed -n 's/.*max=\([0-9]*\) .*/\1/p')" "$max"
    done ;;
16.7) # the visibility pass cut down on the bunnies, at 1 and 4 samples: the pixels each mode shades
    said "(\`shaded_pixels=51457\` at 1 sample, \`53976\` at 4) and \`depth-only\` none (\`shaded_pixels=0\`)"
    bunnies=(--headless --size 400x400 --frames 1 --warmup 0 --bench --scene "$A/bunnies.scene")
    for s in 1:51457 4:53976; do
        for mode in full:${s#*:} no-primitive-id:${s#*:} depth-only:0; do
            run "${mode%:*}_${s%:*}" 16_visibility_buffer "${bunnies[@]}" --samples "${s%:*}" --vis-pass "${mode%:*}"
            printed "${mode%:*}_${s%:*}" "shaded_pixels=${mode#*:} "
        done
    done ;;
06.exactness) # not an exercise: the table "How exact is RGBA16F?", each --accum against chapter 00
    said "| default | max 1/255, 0 % over 1 | max 1, 0 % | max 8, 10.9 % over 1 |"
    said "| overlap (sum > 1) | **max 2**, 0.43 % over 1 | max 1, 0 % | max 8, 26.2 % over 1 |"
    # max and pixels over 1/255 of 76,800 (10.9 % = 8,379; 0.43 % = 333; 26.2 % = 20,128)
    declare -A table=([default_rgba16f]="1 0" [default_rgba32f]="1 0" [default_rgba8]="8 8379"
                      [overlap_rgba16f]="2 333" [overlap_rgba32f]="1 0" [overlap_rgba8]="8 20128")
    for scene in "$A/default.scene" "$src/tests/scenes/overlap.scene"; do
        n=$(basename "$scene" .scene)
        run "forward_$n" 00_forward --headless --size 320x240 --frames 1 --scene "$scene" --screenshot "$out/forward_$n.png"
        for accum in rgba16f rgba32f rgba8; do
            run "${n}_$accum" 06_additive_blending --headless --size 320x240 --frames 1 --scene "$scene" \
                --accum "$accum" --screenshot "$out/${n}_$accum.png"
            line=$("$bin/imgdiff" "$out/forward_$n.png" "$out/${n}_$accum.png" 2>&1 | grep "imgdiff:")
            want=${table[${n}_$accum]}
            equal "$n, $accum: max" "$(sed -n 's/.*max=\([0-9]*\) .*/\1/p' <<<"$line")" "${want% *}"
            near "$n, $accum: pixels over 1/255" "$(sed -n 's/.*over_tol=\([0-9]*\) .*/\1/p' <<<"$line")" "${want#* }"
        done
    done ;;
03.exactness) # not an exercise: the table "How close to forward", both layouts against chapter 00
    said "| 320×240 | 1 | 0.186 | 0 | 0.175 |"
    said "| 200×300 | 1 | 0.221 | 0 | 0.201 |"
    said "| 320×240, \`--time 3\` (orange light moved) | 1 | 0.185 | 0 | 0.174 |"
    said "| 1024×768, \`--time 1.3\` | 1 | 0.185 | 0 | 0.174 |"
    rows=("320x240:0.186:0.175" "200x300:0.221:0.201" "320x240 --time 3:0.185:0.174" "1024x768 --time 1.3:0.185:0.174")
    for row in "${rows[@]}"; do
        IFS=: read -r frame reference compact <<<"$row"
        read -r size time <<<"${frame/ --time/}"
        args=(--headless --frames 1 --size "$size" ${time:+--time "$time"})
        run forward 00_forward "${args[@]}" --screenshot "$out/forward.png"
        for layout in reference:$reference compact:$compact; do
            run "${layout%:*}" 03_fullscreen_phong "${args[@]}" --gbuffer "${layout%:*}" --screenshot "$out/${layout%:*}.png"
            line=$("$bin/imgdiff" "$out/forward.png" "$out/${layout%:*}.png" 2>&1 | grep "imgdiff:")
            got=$(sed -n 's/.*max=\([0-9]*\) .*mean=\([0-9.]*\) .*over_tol=\([0-9]*\) .*/\1 \2 \3/p' <<<"$line")
            # the page gives the mean to 3 digits, imgdiff to 4: within 0.001
            if awk -v g="$got" -v m="${layout#*:}" 'BEGIN { split(g, f, " "); d = f[2] - m
                exit !(f[1] == 1 && f[3] == 0 && d * d <= 1.0001e-6) }'; then
                echo "ok   $frame, ${layout%:*}: max, mean, over 1/255: $got (the page: 1 ${layout#*:} 0)"
            else echo "FAIL $frame, ${layout%:*}: max, mean, over 1/255: $got, the page says 1 ${layout#*:} 0"; fail=1; fi
        done
    done ;;
06.2) # GL_R11F_G11F_B10F as a fourth --accum (on a copy of the chapter), the default scene against chapter 00
    said "40,229 pixels (52.4 %) beyond 1/255, up to 11/255"
    patched_chapter r11f 06_additive_blending 'static const GLenum accum_formats[] = {GL_RGBA16F, GL_RGBA8, GL_RGBA32F};' \
        's/"rgba32f", NULL};/"rgba32f", "r11f_g11f_b10f", NULL};/; s/GL_RGBA8, GL_RGBA32F};/GL_RGBA8, GL_RGBA32F, GL_R11F_G11F_B10F};/'
    frame=(--headless --size 320x240 --frames 1)
    run forward 00_forward "${frame[@]}" --screenshot "$out/forward.png"
    run r11f r11f "${frame[@]}" --accum r11f_g11f_b10f --screenshot "$out/r11f.png"
    line=$("$bin/imgdiff" "$out/forward.png" "$out/r11f.png" 2>&1 | grep "imgdiff:")
    echo "     $line"
    equal "R11F_G11F_B10F against chapter 00: max" "$(sed -n 's/.*max=\([0-9]*\) .*/\1/p' <<<"$line")" 11
    near "pixels beyond 1/255" "$(sed -n 's/.*over_tol=\([0-9]*\) .*/\1/p' <<<"$line")" 40229 ;;
07.2) # the volume pass's depth test GL_GEQUAL: the background's pixels shaded too (on a copy of the chapter)
    patched_chapter gequal 07_face_culling "    .depth_func = GL_GREATER," "/^static const gl_pass_state volume_pass = {\$/,/^};\$/ s/\.depth_func = GL_GREATER,/.depth_func = GL_GEQUAL,/"
    said "\`shaded_pixels=2154464\` both ways at the default 800×600"
    said "at 320×240 one more, 344,665 to 344,666"
    run greater 07_face_culling "${bench[@]}"
    printed greater "shaded_pixels=2154464 "
    run gequal gequal "${bench[@]}"
    printed gequal "shaded_pixels=2154464 "
    run greater_small 07_face_culling "${bench[@]}" --size 320x240
    printed greater_small "shaded_pixels=344665 "
    run gequal_small gequal "${bench[@]}" --size 320x240 --screenshot "$out/gequal.png"
    printed gequal_small "shaded_pixels=344666 "
    equal "pixels beyond 0/255 against the golden" \
        "$("$bin/imgdiff" --tolerance 0 "$src/tests/golden/07_face_culling.png" "$out/gequal.png" 2>&1 |
           sed -n 's/.*over_tol=\([0-9]*\) .*/\1/p')" 0 ;;
07.3) # the stencil pass between the faces: chapter 08 is its answer, counted on the city
    said "this chapter shades \`shaded_pixels=3958724\` and chapter 08 \`shaded_pixels=3116818\`, 21 % fewer"
    run volumes 07_face_culling "${bench[@]}" --scene "$A/city.scene"
    printed volumes "shaded_pixels=3958724 "
    run stencil 08_stencil_volumes "${bench[@]}" --scene "$A/city.scene"
    printed stencil "shaded_pixels=3116818 " ;;
10.5) # TILE_SIZE 8 and 32 (on copies of the chapter): the lit picture the same, the tile views not
    said "45.3 %, 39.2 % and 11.8 % of the pixels move beyond 1/255 at 8, and 57.9 %, 47.5 % and 8.7 % at 32"
    declare -A moved=([8]="45.3 39.2 11.8" [32]="57.9 47.5 8.7") # the page's, to 0.1 %
    for ts in 8 32; do
        patched_chapter "tile$ts" 10_tiled_deferred "enum { TILE_SIZE = 16, VIEW_TILES = 3 };" \
            "s/TILE_SIZE = 16,/TILE_SIZE = $ts,/; s/TILE_SIZE 16\\\\n/TILE_SIZE $ts\\\\n/"
        run "lit_$ts" "tile$ts" --headless --size 320x240 --frames 1 --screenshot "$out/lit_$ts.png"
        equal "TILE_SIZE $ts: lit pixels beyond 0/255 against the golden" \
            "$("$bin/imgdiff" --tolerance 0 "$src/tests/golden/10_tiled_deferred.png" "$out/lit_$ts.png" 2>&1 |
               sed -n 's/.*over_tol=\([0-9]*\) .*/\1/p')" 0
        read -r -a want <<<"${moved[$ts]}"
        k=0
        for view in "tiles|--lights 256 --view tiles" "overdraw|--lights 256 --view overdraw" \
                    "crowd_tiles|--scene $src/tests/scenes/tile_crowd.scene --view tiles"; do
            read -r -a args <<<"${view#*|}"
            run "${view%%|*}_$ts" "tile$ts" --headless --size 320x240 --frames 1 "${args[@]}" \
                --screenshot "$out/${view%%|*}_$ts.png"
            equal "TILE_SIZE $ts: ${view%%|*}'s pixels beyond 1/255 against its golden (%)" \
                "$("$bin/imgdiff" --tolerance 1 "$src/tests/golden/10_tiled_deferred_${view%%|*}.png" \
                   "$out/${view%%|*}_$ts.png" 2>&1 | sed -n 's/.* (\([0-9.]*\) %).*/\1/p' | awk '{ printf "%.1f", $1 }')" "${want[$k]}"
            k=$((k + 1))
        done
    done ;;
12.5) # the nearest point of each bounding sphere as the sort key (a copy of common/gl/gpu_scene.c)
    said "(magenta 7.84 now before amber 7.65, and the cyan pane 5.32 after the ball 5.70"
    said "\`12_transparency_glass\`, 3,825 of its 76,800 pixels beyond 1/255 (max 60/255)"
    patched_common nearest 12_transparency common/gl/gpu_scene.c \
        "gs->sort_keys[k] = (gpu_sort_key){glm_vec3_distance2(gs->view.eye, gs->bounds[i]), i};" \
        "s/(gpu_sort_key){glm_vec3_distance2(gs->view.eye, gs->bounds\[i\]), i}/(gpu_sort_key){glm_vec3_distance(gs->view.eye, gs->bounds[i]) - gs->bounds[i][3], i}/"
    G=$A/glass.scene T=$src/tests/scenes
    for golden in "glass|--scene $G" "glass_sort_none|--scene $G --sort none" "glass_overdraw|--scene $G --view overdraw" \
                  "glass_inside|--scene $T/glass_inside.scene" "glass_same_depth|--scene $T/glass_same_depth.scene"; do
        read -r -a args <<<"${golden#*|}"
        name=${golden%%|*}
        run "$name" nearest --headless --size 320x240 --frames 1 "${args[@]}" --screenshot "$out/$name.png"
        if [ "$name" = glass ]; then
            near "glass: pixels beyond 1/255 against its golden" "$(over "$src/tests/golden/12_transparency_glass.png" "$out/glass.png")" 3825
        else # the goldens' own bound (tests/chapters/chapter_12.cmake): 1/255, at most 0.01 % beyond
            "$bin/imgdiff" --quiet --tolerance 1 --max-fraction 0.0001 "$src/tests/golden/12_transparency_$name.png" \
                "$out/$name.png" >/dev/null 2>&1 && echo "ok   $name: its golden still passes" ||
                { echo "FAIL $name: its golden no longer passes"; fail=1; }
        fi
    done ;;
01.2) # the framebuffer broken on purpose, twice (on copies of the chapter)
    patched_chapter zero_width 01_fbo_setup "GL_RGBA8, width, height, 0," "s/GL_RGBA8, width, height, 0,/GL_RGBA8, 0, height, 0,/"
    patched_chapter depth_as_colour 01_fbo_setup "    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, state.depth);" "/^    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, state.depth);\$/a\\    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, state.depth);"
    said "both runs exit with status 1, draw nothing and print \`offscreen framebuffer 320x240: GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT\`"
    for broken in zero_width depth_as_colour; do
        (cd "$src" && "$out/bin/$broken" --headless --size 320x240 --frames 1 --screenshot "$out/$broken.png") \
            >"$out/$broken.log" 2>&1
        rc=$?
        [ "$rc" -eq 77 ] && { echo "skip: no GL context"; exit 77; }
        equal "$broken's exit status" "$rc" 1
        printed "$broken" "offscreen framebuffer 320x240: GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT"
        [ ! -e "$out/$broken.png" ] && echo "ok   $broken drew nothing" || { echo "FAIL $broken wrote a picture"; fail=1; }
    done
    run put_back 01_fbo_setup --headless --size 320x240 --frames 1 --screenshot "$out/put_back.png"
    equal "pixels beyond 0/255 against the golden, put back" \
        "$("$bin/imgdiff" --tolerance 0 "$src/tests/golden/01_fbo_setup.png" "$out/put_back.png" 2>&1 |
           sed -n 's/.*over_tol=\([0-9]*\) .*/\1/p')" 0 ;;
13.4) # each edge sample shaded at its own rebuilt point, not the centre's ray, city at 800x800 (on a copy of the shaders)
    said "7,976 pixels beyond 1/255 (1.25 %, max 37/255) instead of 71 (max 6/255)"
    said "7,618 pixels between the two deferred pictures"
    shader_copy
    frag=$out/data/shaders/msaa_deferred.frag
    grep -q '^            su.position = centre_on_plane(p, s, su.normal);$' "$frag" ||
        { echo "FAIL: msaa_deferred.frag's per-sample pass does not move the samples to the centre's ray"; exit 1; }
    sed -i 's/^            su.position = centre_on_plane(p, s, su.normal);$/            su.position = sample_point(p, s);/' "$frag"
    city=(--headless --size 800x800 --frames 1 --scene "$A/city.scene")
    run forward 13_msaa "${city[@]}" --renderer forward --screenshot "$out/forward.png"
    run centre 13_msaa "${city[@]}" --screenshot "$out/centre.png"
    run own 13_msaa "${city[@]}" --data-dir "$out/data" --screenshot "$out/own.png"
    # the page's pixels beyond 1/255 and max for each pair
    for pair in "forward centre 71 6" "forward own 7976 37" "centre own 7618 37"; do
        read -r a b over_want max_want <<<"$pair"
        line=$("$bin/imgdiff" "$out/$a.png" "$out/$b.png" 2>&1 | grep "imgdiff:")
        equal "$a against $b: max" "$(sed -n 's/.*max=\([0-9]*\) .*/\1/p' <<<"$line")" "$max_want"
        near "$a against $b: pixels beyond 1/255" "$(sed -n 's/.*over_tol=\([0-9]*\) .*/\1/p' <<<"$line")" "$over_want"
    done ;;
13.3) # is_edge without its plane test, on the city at 800x800 against forward (on a copy of the shaders)
    said "71 pixels beyond 1/255 (max 6/255, within \`13_vs_forward_msaa_city\`'s 0.015 %) before, 327 after (0.051 %, max 54/255)"
    said "253 pixels between the two deferred pictures"
    shader_copy
    frag=$out/data/shaders/msaa_deferred.frag
    grep -q '^        if (abs(dot(sample_point(p, s) - p0, n)) > tolerance)$' "$frag" ||
        { echo "FAIL: msaa_deferred.frag's is_edge has no plane test to drop"; exit 1; }
    sed -i '/^    vec3 n = gbuffer_read_sample(p, 0, vec3(0.0)).normal, p0 = sample_point(p, 0);$/,/^            return true;$/d' "$frag"
    city=(--headless --size 800x800 --frames 1 --scene "$A/city.scene")
    run forward 13_msaa "${city[@]}" --renderer forward --screenshot "$out/forward.png"
    run kept 13_msaa "${city[@]}" --screenshot "$out/kept.png"
    run dropped 13_msaa "${city[@]}" --data-dir "$out/data" --screenshot "$out/dropped.png"
    near "with the plane test against forward, pixels beyond 1/255" "$(over "$out/forward.png" "$out/kept.png")" 71
    near "without it" "$(over "$out/forward.png" "$out/dropped.png")" 327
    near "the two deferred pictures" "$(over "$out/kept.png" "$out/dropped.png")" 253 ;;
16.3) # 15 bits of triangle, 17 of object: the scenes refused (the chapter built with the header changed)
    patched_chapter bits15 16_visibility_buffer "SHADER_VIS_TRIANGLE_BITS" "" \
        common/base/shader_layout.h "s/X(VIS_TRIANGLE_BITS, 20)/X(VIS_TRIANGLE_BITS, 15)/"
    said "four scenes, each exiting with status 2"
    said "\`bunnies.scene: mesh 'bunny' has 58784 triangles; the visibility buffer's ids hold at most 32768 a mesh (15 bits of triangle)\`"
    said "\`pbr_teapots\`, \`teapots\` and \`teapots_probes\` the same for their mesh 'teapot' of 36672 triangles"
    said "\`city\`, \`default\`, \`glass\`, \`sphere\` and \`spots\` are still taken"
    for scene in bunnies:bunny:58784 pbr_teapots:teapot:36672 teapots:teapot:36672 teapots_probes:teapot:36672; do
        IFS=: read -r file mesh triangles <<<"$scene"
        (cd "$src" && "$out/bin/bits15" --headless --size 64x48 --frames 1 --scene "$A/$file.scene") >"$out/$file.log" 2>&1
        rc=$?
        [ "$rc" -eq 77 ] && { echo "skip: no GL context"; exit 77; }
        equal "$file refused, exit status" "$rc" 2
        printed "$file" "$file.scene: mesh '$mesh' has $triangles triangles; the visibility buffer's ids hold at most 32768 a mesh (15 bits of triangle)"
    done
    for file in city default glass sphere spots; do
        run "$file" bits15 --headless --size 64x48 --frames 1 --scene "$A/$file.scene"
        if grep -q "the visibility buffer's ids hold" "$out/$file.log"; then echo "FAIL $file refused"; fail=1; else
            echo "ok   $file taken"; fi
    done ;;
16.6) # the edge pass's samples shaded with the one-sample pass's clamp (on a copy of the shaders), against 13 at 4 samples
    said "default 271 (43/255), spots 306 (82/255), teapots 2,705 (33/255), city 2,862 (32/255), and the bunnies at 160×120 4,018 (20.9 %, 51/255)"
    shader_copy
    frag=$out/data/shaders/visibility_shade.frag
    grep -qF ': shade_id(ids[s], one, range, depth);' "$frag" || { echo "FAIL: visibility_shade.frag's edge pass has no shade_id(ids[s], one"; exit 1; }
    sed -i 's/: shade_id(ids\[s\], one, range, depth);/: shade_id(ids[s], true, range, depth);/' "$frag"
    # each scene of agree.16_msaa4_* (tests/chapters/chapter_16.cmake): its frame, the page's pixels beyond 1/255 and max
    for row in "default|$A/default.scene|320x240|271|43" "spots|$A/spots.scene|320x240|306|82" \
               "teapots|$A/teapots.scene|320x240|2705|33" "city|$A/city.scene|320x240|2862|32" \
               "bunnies|$A/bunnies.scene|160x120|4018|51"; do
        IFS='|' read -r name scene size over_want max_want <<<"$row"
        frame=(--headless --frames 1 --size "$size" --samples 4 --scene "$scene")
        run "forward_$name" 13_msaa "${frame[@]}" --renderer forward --screenshot "$out/forward_$name.png"
        run "clamped_$name" 16_visibility_buffer "${frame[@]}" --data-dir "$out/data" --screenshot "$out/clamped_$name.png"
        line=$("$bin/imgdiff" "$out/forward_$name.png" "$out/clamped_$name.png" 2>&1 | grep "imgdiff:")
        equal "$name against forward MSAA: max" "$(sed -n 's/.*max=\([0-9]*\) .*/\1/p' <<<"$line")" "$max_want"
        near "$name: pixels beyond 1/255" "$(sed -n 's/.*over_tol=\([0-9]*\) .*/\1/p' <<<"$line")" "$over_want"
    done ;;
02.5) # chapter 07 with reversed-z: its volume pass mirrored, the shader's background test, the guard let through
    said "68 pixels of the city at 800×800 change (beyond 1/255), and against chapter 00 only 6 are left beyond 1/255 (max 30/255) instead of the default's 63"
    said "the patched chapter draws the default layout's picture unchanged"
    patched_chapter reversed 07_face_culling "    if (!deferred_volumes_render(&state.dv, &state.g, &a->gs, a->target.id, &f))" "$(cat <<'SED'
/^    const deferred_volumes_frame f = {$/i\
    gl_pass_state pass = state.pass; /* mirrored for a reversed-Z layout */\
    gpu_scene mirrored;\
    gbuffer_depth_test_begin(&state.g, &a->gs, &mirrored, &pass);
s/^        \.volume_state = &state\.pass,$/        .volume_state = \&pass,/
/^    if (!deferred_volumes_render(&state\.dv, &state\.g, &a->gs, a->target\.id, &f))$/{
N
s/.*/    bool drawn = deferred_volumes_render(\&state.dv, \&state.g, \&mirrored, a->target.id, \&f);\
    gbuffer_depth_test_end(\&state.g);\
    if (!drawn)\
        return false;/
}
s/\.cleanup = cleanup, \.key = key};$/.cleanup = cleanup, .key = key,\
                             .takes_reversed_z = true};/
SED
)"
    shader_copy
    frag=$out/data/shaders/light_volume.frag
    grep -q '^    if (depth >= 1.0 || d > v_volume_radius) {$' "$frag" || { echo "FAIL: light_volume.frag has no depth >= 1.0"; exit 1; }
    sed -i 's/^    if (depth >= 1.0 || d > v_volume_radius) {$/    if (gbuffer_is_background(depth) || d > v_volume_radius) {/' "$frag"
    city=(--headless --size 800x800 --frames 1 --scene "$A/city.scene")
    run forward 00_forward "${city[@]}" --screenshot "$out/forward.png"
    run default 07_face_culling "${city[@]}" --screenshot "$out/default.png"
    run reversed reversed "${city[@]}" --data-dir "$out/data" --gbuffer reversed-z --screenshot "$out/reversed.png"
    run reversed_default reversed "${city[@]}" --data-dir "$out/data" --screenshot "$out/reversed_default.png"
    near "the default layout against chapter 00, pixels beyond 1/255" "$(over "$out/forward.png" "$out/default.png")" 63
    near "reversed-z against chapter 00" "$(over "$out/forward.png" "$out/reversed.png")" 6
    near "the city pixels that change, default to reversed-z" "$(over "$out/default.png" "$out/reversed.png")" 68
    equal "pixels the patch moves with the default layout (beyond 0/255)" \
        "$("$bin/imgdiff" --tolerance 0 "$out/default.png" "$out/reversed_default.png" 2>&1 |
           sed -n 's/.*over_tol=\([0-9]*\) .*/\1/p')" 0 ;;
17.5) # the march in one step (a copy of the shaders, SHADER_AO_STEPS 1 in ssao.frag), against the exact AO
    said "mean error 0.0136 (0.0112 with four steps) and 4.26 % of pixels beyond 0.1 (3.06 %)"
    said "5.34 % (2.31 %), then the border, 2.96 % (2.01 %), and the silhouettes, 2.47 % (1.81 %)"
    said "near the thin post it gets better, 1.33 % (18.12 %)"
    shader_copy
    sed -i '1a #undef SHADER_AO_STEPS\n#define SHADER_AO_STEPS 1' "$out/data/shaders/ssao.frag"
    grep -q '^#define SHADER_AO_STEPS 1$' "$out/data/shaders/ssao.frag" || { echo "FAIL: the one step not set"; exit 1; }
    reference=$bin/../tests/test_ssao_reference # hard.ssao_reference's program and arguments, the defaults only
    (cd "$src" && COURSE_SHADER_DIR=$out/data/shaders "$reference" tests/scenes/ssao_boxes.scene 0.5 0.013 0.1 0.035 \
        0.02 0.025 0.2 0.001 16 2) >"$out/one_step.log" 2>&1
    rc=$?
    [ "$rc" -eq 77 ] && { echo "skip: no GL context"; exit 77; }
    equal "the reference test's exit status with one step" "$rc" 1
    # the shares beyond 0.1, in hundredths of a per cent (within 1 %: llvmpipe's last bits move with the CPU)
    share() { sed -n "s/.*$1.* \([0-9.]*\) % .*beyond 0.100.*/\1/p" "$out/one_step.log" | head -n 1 |
              awk '{ printf "%d", $1 * 100 + 0.5 }'; }
    near "one step: pixels beyond 0.1 (0.01 %)" "$(share 'scene: mean error')" 426
    near "one step: the open floor's (0.01 %)" "$(share '  open ')" 534
    near "one step: the border's (0.01 %)" "$(share '  border ')" 296
    near "one step: the silhouettes' (0.01 %)" "$(share '  silhouette ')" 247
    near "one step: near the thin post (0.01 %)" "$(share '  thin ')" 133 ;;
03.3) # the background shaded too: the same picture, every pixel counted (on a copy of the shaders)
    said "\`shaded_pixels\` goes from 43,125 to 76,800, every pixel"
    shader_copy
    frag=$out/data/shaders/deferred_fullscreen.frag
    grep -q '^        discard;$' "$frag" || { echo "FAIL: deferred_fullscreen.frag has no discard to remove"; exit 1; }
    sed -i 's/^        discard;$/        ;/' "$frag"
    run kept 03_fullscreen_phong "${bench[@]}" --size 320x240
    printed kept "shaded_pixels=43125 "
    run removed 03_fullscreen_phong "${bench[@]}" --size 320x240 --data-dir "$out/data" --screenshot "$out/removed.png"
    printed removed "shaded_pixels=76800 "
    equal "pixels beyond 0/255 against the golden" \
        "$("$bin/imgdiff" --tolerance 0 "$src/tests/golden/03_fullscreen_phong.png" "$out/removed.png" 2>&1 |
           sed -n 's/.*over_tol=\([0-9]*\) .*/\1/p')" 0 ;;
*)
    echo "FAIL: no exercise $exercise here"; exit 1 ;;
esac
exit "$fail"
