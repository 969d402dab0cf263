#!/usr/bin/env bash
# run_pbr_exercise.sh CHAPTER18 IMGDIFF SOURCE_DIR OUT_DIR - docs/18_pbr_materials.md's exercise 2,
# performed as the page words it: the sed line that copies assets/scenes/pbr_teapots.scene without its
# normal maps (its paths rewritten to the data folder's, so the copy works from any folder), then the
# lit picture against tests/golden/18_pbr_teapots.png. The page's count of pixels beyond 1/255 must be
# the one measured, within 1 % (llvmpipe's arithmetic differs in the last bits between CPUs).
set -u
chapter=$1 imgdiff=$2 src=$3 out=$4
mkdir -p "$out"
page=$src/docs/18_pbr_materials.md
command=$(grep -o "sed -e 's# normal_map \[^ \]\*##'[^\`]*" "$page" | head -n 1)
[ -n "$command" ] || { echo "FAIL: exercise 2 no longer gives its sed line"; exit 1; }
(cd "$src" && eval "${command/my_teapots.scene/$out/my_teapots.scene}") || { echo "FAIL: $command"; exit 1; }
grep -q normal_map "$out/my_teapots.scene" && { echo "FAIL: the copy still has normal maps"; exit 1; }
"$chapter" --headless --size 320x240 --frames 1 --scene "$out/my_teapots.scene" --screenshot "$out/lit.png" \
    >"$out/run.log" 2>&1
rc=$?
[ "$rc" -eq 77 ] && { echo "skip: no GL context"; exit 77; }
[ "$rc" -eq 0 ] || { echo "FAIL: the copy does not render (exit $rc)"; cat "$out/run.log"; exit 1; }
line=$("$imgdiff" "$src/tests/golden/18_pbr_teapots.png" "$out/lit.png" 2>&1 | grep "imgdiff:")
echo "$line"
got=$(sed -n 's/.*over_tol=\([0-9]*\).*/\1/p' <<<"$line")
said=$(grep -o "[0-9,]* pixels of the lit picture differ" "$page" | head -n 1 | tr -d ',' | cut -d' ' -f1)
[ -n "$said" ] || { echo "FAIL: exercise 2 no longer says how many pixels differ"; exit 1; }
if awk "BEGIN { d = $got - $said; exit !(d * d <= ($said / 100) ^ 2) }"; then
    echo "ok   $got pixels differ; the page says $said"
else
    echo "FAIL: $got pixels differ; the page says $said"; exit 1
fi
