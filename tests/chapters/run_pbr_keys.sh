#!/usr/bin/env bash
# run_pbr_keys.sh IMGDIFF OUTDIR CHAPTER_18 SCENE - chapter 18's keys, driven headless by a --script:
#   1. a number key shows that view: 4 is --view roughness to the byte, 1 the lit picture again
#   2. + doubles the exposure (--exposure 2's picture), - halves it back (the first picture)
#   3. Y doubles the ambient light (--ambient 2's picture)
#   4. L moves every light: the picture changes; J moves them back: the first picture (within 1/255:
#      0.25 added and taken away again in float)
# Skips (77) without a GL context; never passes without checking.
set -u
imgdiff=$1 outdir=$2 ch18=$3 scene=$4
args=(--headless --size 160x120 --scene "$scene")
mkdir -p "$outdir"
out="$outdir/pbr_keys"
rm -f "$out".*
fail=0
say() { echo "$1"; case $1 in FAIL*) fail=1 ;; esac; }
same() { # same EXPECTED ACTUAL WHAT [TOLERANCE]: byte for byte unless a tolerance is given
  if "$imgdiff" --quiet --tolerance "${4:-0}" --max-fraction 0 "$1" "$2" >"$out.diff" 2>&1; then say "ok   $3"
  else say "FAIL $3: $(tail -1 "$out.diff") ($2)"; fi
}
cat >"$out.script" <<SCRIPT
0 screenshot $out.lit.png
1 key 4
1 screenshot $out.key4.png
2 key 1
2 screenshot $out.key1.png
3 key +
3 screenshot $out.plus.png
4 key -
4 screenshot $out.minus.png
5 key L
5 screenshot $out.moved.png
6 key J
6 screenshot $out.moved_back.png
7 key Y
7 screenshot $out.ambient.png
7 quit
SCRIPT
"$ch18" "${args[@]}" --script "$out.script" >"$out.stdout" 2>"$out.stderr"
rc=$?
if [ "$rc" -eq 77 ]; then echo "skip: no GL context: $(head -1 "$out.stderr")"; exit 77; fi
[ "$rc" -eq 0 ] || { echo "FAIL 18 --script: exit $rc: $(head -3 "$out.stderr")"; exit 1; }
"$ch18" "${args[@]}" --view roughness --screenshot "$out.roughness.png" 2>/dev/null || say "FAIL --view roughness"
"$ch18" "${args[@]}" --exposure 2 --screenshot "$out.exposure2.png" 2>/dev/null || say "FAIL --exposure 2"
"$ch18" "${args[@]}" --ambient 2 --screenshot "$out.ambient2.png" 2>/dev/null || say "FAIL --ambient 2"
same "$out.roughness.png" "$out.key4.png" "key 4: the roughness view"
same "$out.lit.png" "$out.key1.png" "key 1: the lit view again"
same "$out.exposure2.png" "$out.plus.png" "+: the exposure doubled"
same "$out.lit.png" "$out.minus.png" "-: the exposure back to 1"
same "$out.ambient2.png" "$out.ambient.png" "Y: the ambient light doubled"
same "$out.lit.png" "$out.moved_back.png" "L then J: the lights where they were" 1
if "$imgdiff" --quiet --tolerance 1 --max-fraction 0 "$out.lit.png" "$out.moved.png" >/dev/null 2>&1; then
  say "FAIL L: moving the lights changed nothing"
else
  say "ok   L: moving the lights changes the picture"
fi
grep -q "lights moved by 0.25 0.00 0.00" "$out.stderr" "$out.stdout" && say "ok   L: logged" ||
  say "FAIL L: no 'lights moved by 0.25 0.00 0.00' line"
exit "$fail"
