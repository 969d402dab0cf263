#!/usr/bin/env bash
# run_shadow_exercise.sh CHAPTER14 IMGDIFF OUT_DIR SCENES_DIR - docs/14_shadows.md's exercise 2,
# performed: on shadow_grazing.scene without a normal offset, a slope bias of 0 leaves acne over most
# of the picture, 0.5 over a tenth or more, 1 none (the picture then differs from the default one only
# by the default's 0.25 texels of normal offset, at the box: under 0.2 %); on shadow_contact.scene a
# slope bias above the default 2 moves more pixels at 4, 8 and 16 (each more than the last, more than
# 200 at 16), the most-changed one under the ball, where its shadow should touch it.
set -u
chapter=$1 imgdiff=$2 out=$3 scenes=$4
mkdir -p "$out"
render() { # NAME SCENE ARGS...
    local name=$1 scene=$2
    shift 2
    "$chapter" --headless --size 320x240 --frames 1 --scene "$scenes/$scene" "$@" --screenshot "$out/$name.png" \
        >"$out/$name.log" 2>&1
    local rc=$?
    [ "$rc" -eq 77 ] && { echo "skip: no GL context"; exit 77; }
    [ "$rc" -eq 0 ] || { echo "FAIL: $name exit $rc"; cat "$out/$name.log"; exit 1; }
}
field() { sed -n "s/.*$2=\([0-9.]*\).*/\1/p" <<<"$1"; } # a number after NAME= in imgdiff's line
compare() { "$imgdiff" "$out/$1.png" "$out/$2.png" 2>&1 | grep "imgdiff:"; }
fail=0
check() { # CONDITION MESSAGE
    if awk "BEGIN { exit !($1) }"; then echo "ok   $2"; else echo "FAIL $2"; fail=1; fi
}

render grazing shadow_grazing.scene
for sb in 0 0.5 1; do
    render "grazing_$sb" shadow_grazing.scene --normal-offset 0 --slope-bias "$sb"
    line=$(compare grazing "grazing_$sb")
    pct=$(sed -n 's/.*over_tol=[0-9]* (\([0-9.]*\) %).*/\1/p' <<<"$line")
    echo "     slope bias $sb: $line"
    case $sb in
        0) check "$pct > 50" "slope bias 0: acne on ${pct} % of the picture (more than half)" ;;
        0.5) check "$pct > 10" "slope bias 0.5: acne left on ${pct} % (more than a tenth)" ;;
        1) check "$pct < 0.2" "slope bias 1: ${pct} % differ from the default picture (no acne)" ;;
    esac
done

render contact shadow_contact.scene
last=0
for sb in 4 8 16; do
    render "contact_$sb" shadow_contact.scene --slope-bias "$sb"
    line=$(compare contact "contact_$sb")
    count=$(field "$line" over_tol)
    echo "     slope bias $sb: $line"
    check "$count > $last" "slope bias $sb: $count pixels moved, more than at the bias before ($last)"
    last=$count
    at=$(sed -n 's/.*max=[0-9]* at (\([0-9]*\),\([0-9]*\)).*/\1 \2/p' <<<"$line")
done
check "$last > 200" "slope bias 16: more than 200 pixels moved"
read -r x y <<<"$at"
check "$x >= 180 && $x <= 300 && $y >= 150 && $y <= 240" "the most-changed pixel ($x,$y) lies under the ball"
exit "$fail"
