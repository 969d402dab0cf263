#!/usr/bin/env bash
# run_overlay_fit.sh IMGDIFF CHAPTER_07 CHAPTER_11: the overlay as a learner reads it, headless with
# --script (the window draws the same picture):
#   1. it never runs off the picture: at 400x300 in compare mode (its longest lines are wider than
#      that) no text pixel lies in the last 4 columns; the lines wrap instead (the box keeps PAD, 4
#      font units, from the edge)
#   2. F1's key list replaces the overlay while it shows: the picture with H and F1 on is the one with
#      F1 alone, to the pixel (before, both were drawn over each other)
#   3. it names what the chapter counts: "lighting fragments" in chapter 07, "light-loop iterations"
#      in chapter 11 (its tiles' and clusters' loops)
#   4. G's light is labelled where it is: the picture right after G and the one a key later (which
#      takes the label away) differ only by a darkened box with white text
#   5. Backspace brings back the lights the run started with: after +, G and Backspace the overlay
#      counts the scene's lights again and the picture is the headless one, to the pixel
# Skips (77) without a GL context.
set -u
imgdiff=$1 ch07=$2 ch11=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
say() { echo "$1"; case $1 in FAIL*) fail=1 ;; esac; }
run() { # run BINARY SCRIPT ARGS...
  "$1" --headless --paused --script "$2" "${@:3}" >"$tmp/out" 2>"$tmp/err"
  local rc=$?
  [ $rc -eq 77 ] && { echo "skip: no GL context"; exit 77; }
  [ $rc -eq 0 ] || say "FAIL $(basename "$1") $*: exit $rc: $(head -2 "$tmp/err")"
}

# 1. The right edge, from the PNG's pixels (tests/chapters/msaa_edges.py reads PNGs with the standard library).
printf '0 key H\n1 screenshot %s\n1 quit\n' "$tmp/narrow.png" >"$tmp/s1"
run "$ch11" "$tmp/s1" --size 400x300 --compare split
/usr/bin/python3 - "$tmp/narrow.png" <<'PY' && say "ok   1. no overlay text in the last 4 columns at 400x300" || say "FAIL 1. the overlay's text runs off the right edge"
import sys
sys.path.insert(0, "tests/chapters")
from msaa_edges import load
w, h, rows = load(sys.argv[1])
white = sum(1 for y in range(h // 2) for x in range(w - 4, w) if rows[y][x] == (255, 255, 255))
print(f"     white pixels in the last 4 columns of the top half: {white}")
sys.exit(1 if white else 0)
PY

# 2. F1 over the overlay.
printf '0 key H\n1 key F1\n2 screenshot %s\n2 quit\n' "$tmp/both.png" >"$tmp/s2"
printf '1 key F1\n2 screenshot %s\n2 quit\n' "$tmp/keys.png" >"$tmp/s3"
printf '0 key H\n2 screenshot %s\n2 quit\n' "$tmp/overlay.png" >"$tmp/s4"
for s in s2 s3 s4; do run "$ch07" "$tmp/$s" --size 640x480; done
"$imgdiff" --quiet --tolerance 0 --max-fraction 0 "$tmp/keys.png" "$tmp/both.png" >/dev/null 2>&1 &&
  say "ok   2. with F1 shown, the overlay is not drawn under it" || say "FAIL 2. F1 and the overlay are drawn together"
"$imgdiff" --quiet --tolerance 0 --max-fraction 0 "$tmp/keys.png" "$tmp/overlay.png" >/dev/null 2>&1 &&
  say "FAIL 2. the key list and the overlay look the same (the check above proves nothing)"

# 3. The count's name.
printf '0 key H\n1 overlay\n1 quit\n' >"$tmp/s5"
run "$ch07" "$tmp/s5" --size 320x240
grep -q '^overlay: lighting fragments [0-9]' "$tmp/out" && say "ok   3. chapter 07 counts lighting fragments" ||
  say "FAIL 3. chapter 07's overlay: $(grep -i 'fragments\|iterations' "$tmp/out")"
run "$ch11" "$tmp/s5" --size 320x240
grep -q '^overlay: light-loop iterations [0-9]' "$tmp/out" && say "ok   3. chapter 11 counts light-loop iterations" ||
  say "FAIL 3. chapter 11's overlay: $(grep -i 'fragments\|iterations' "$tmp/out")"

# 4. The label.
printf '1 key G\n1 screenshot %s\n2 key C\n2 screenshot %s\n2 quit\n' "$tmp/label.png" "$tmp/nolabel.png" >"$tmp/s6"
run "$ch07" "$tmp/s6" --size 640x480
/usr/bin/python3 - "$tmp/nolabel.png" "$tmp/label.png" <<'PY' && say "ok   4. G's light is labelled" || say "FAIL 4. no label at G's light"
import sys
sys.path.insert(0, "tests/chapters")
from msaa_edges import load
w, h, plain = load(sys.argv[1])
_, _, label = load(sys.argv[2])
changed = [(x, y) for y in range(h) for x in range(w) if plain[y][x] != label[y][x]]
text = sum(1 for x, y in changed if label[y][x] == (255, 255, 255))
other = sum(1 for x, y in changed if label[y][x] != (255, 255, 255) and any(a > b for a, b in zip(label[y][x], plain[y][x])))
print(f"     label: {len(changed)} pixels changed, {text} of them white text, {other} neither text nor darkened")
sys.exit(0 if text >= 20 and other == 0 else 1)
PY

# 5. Backspace.
printf '0 key H\n0 overlay\n1 key =\n2 key G\n3 key Backspace\n4 key H\n4 overlay\n4 screenshot %s\n4 quit\n' "$tmp/back.png" >"$tmp/s7"
run "$ch07" "$tmp/s7" --size 320x240
counts=$(sed -n 's/^overlay: lights \([0-9]*\) active.*/\1/p' "$tmp/out" | tr '\n' ' ')
"$ch07" --headless --size 320x240 --screenshot "$tmp/start.png" >/dev/null 2>&1
read -r first last <<<"$counts"
if [ -n "${last:-}" ] && [ "$first" = "$last" ] &&
   "$imgdiff" --quiet --tolerance 0 --max-fraction 0 "$tmp/start.png" "$tmp/back.png" >/dev/null 2>&1; then
  say "ok   5. Backspace: $first lights again after + and G, and the start's picture"
else
  say "FAIL 5. Backspace: the overlay's counts were '$counts', or the picture is not the start's"
fi
exit $fail
