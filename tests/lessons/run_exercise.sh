#!/usr/bin/env bash
# run_exercise.sh BIN_DIR SOURCE_DIR OUT_DIR EXERCISE - one page exercise performed as its text says
# (EXERCISE: 00.2 is docs/00_*.md's exercise 2): the runs it names, and each target it states checked
# twice, in the page's words (so the page cannot drift) and in what the run printed or drew.
# Exit 0 when every target is met, 1 when one is not, 77 without a GL context.
set -u
source "$(dirname "$0")/../lib/args.sh"
args_expect 4 "$@"
bin=$1 src=$2 out=$3 exercise=$4
args_fresh_dir "$out"
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
    (cd "$src" && "$bin/$chapter" "$@") >"$out/$name.log" 2>&1
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
bench=(--headless --frames 1 --warmup 0 --bench)

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
    equal "the default against chapter 00, pixels beyond 1/255" "$(over "$out/forward.png" "$out/default.png")" 63
    equal "compact-d24s8 against chapter 00" "$(over "$out/forward.png" "$out/d24s8.png")" 70
    equal "the two layouts" "$(over "$out/default.png" "$out/d24s8.png")" 78 ;;
04.1) # the lighting fragments at radius 2, 3 and 8 (the pictures: golden.04_light_volumes_radius2, _radius8)
    said "34,518 at radius 2, 76,988 at the default 3, 326,385 at 8"
    for r in 2:34518 3:76988 8:326385; do
        run "radius_${r%:*}" 04_light_volumes "${bench[@]}" --size 320x240 --radius "${r%:*}"
        printed "radius_${r%:*}" "shaded_pixels=${r#*:} "
    done ;;
*)
    echo "FAIL: no exercise $exercise here"; exit 1 ;;
esac
exit "$fail"
