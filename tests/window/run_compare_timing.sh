#!/usr/bin/env bash
# run_compare_timing.sh CHAPTER: compare mode times both sides, and the places that show them agree.
# Runs CHAPTER headless at 320x240 (--warmup 0, 12 frames):
#   0. --renderer forward --bench: forward's frame alone, the yardstick
#   A. --compare split --bench: the bench line has forward's whole frame as one pass,
#      compare_forward_ms, and the composing as another, compare_compose_ms; none of forward's own
#      passes (light lists, depth pre-pass, shading) is counted as the chapter's; compare_forward_ms
#      is at least 0.1 x forward alone (one forward frame each, run one after the other: 10x is
#      slack for a loaded machine, while the defect this catches read 0.00 ms)
#   B. --compare split --script (overlay printed twice) --verbose: every title names forward's time
#      (at least 0.1 x forward alone, as in A) apart from the chapter's, and the chapter's passes add
#      up to the chapter's figure, not to the frame with forward in it:
#        0.75 x own - 0.02 <= sum(passes) <= own + 0.005 x (passes + 1)
#      (the bounds of run_window_timing.sh: the frame adds to its passes only an idle glFinish);
#      each overlay printed shows the latest title's two figures, to the digit (the same average)
# Skips (77) without a GL context.
set -u
bin=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
say() { echo "$1"; case $1 in FAIL*) fail=1 ;; esac; }
common=(--headless --size 320x240 --frames 12 --warmup 0)

"$bin" "${common[@]}" --renderer forward --bench >"$tmp/forward" 2>"$tmp/err"
rc=$?
[ $rc -eq 77 ] && { echo "skip: no GL context"; exit 77; }
[ $rc -eq 0 ] || { echo "FAIL forward --bench: exit $rc: $(head -2 "$tmp/err")"; exit 1; }

"$bin" "${common[@]}" --compare split --bench >"$tmp/bench" 2>"$tmp/err"
rc=$?
[ $rc -eq 0 ] || { echo "FAIL A. compare --bench: exit $rc: $(head -2 "$tmp/err")"; exit 1; }
printf '3 overlay\n8 overlay\n11 quit\n' >"$tmp/script"
"$bin" "${common[@]}" --compare split --verbose --script "$tmp/script" >"$tmp/out" 2>"$tmp/err"
rc=$?
[ $rc -eq 0 ] || { echo "FAIL B. compare --script: exit $rc: $(head -2 "$tmp/err")"; exit 1; }

field() { sed -n "s/^bench:.* $1=\([^ ]*\).*/\1/p" "$2"; }
line=$(grep '^bench:' "$tmp/bench")
fwd=$(field compare_forward_ms "$tmp/bench")
compose=$(field compare_compose_ms "$tmp/bench")
alone=$(field median_ms "$tmp/forward")
if [ -z "$fwd" ] || [ -z "$compose" ]; then
  say "FAIL A. the bench line lacks compare_forward_ms or compare_compose_ms: $line"
else
  say "ok   A. forward's frame is one pass (compare_forward_ms=$fwd), composing another ($compose)"
fi
for pass in light_lists depth_pre-pass shading; do
  case " $line " in *" ${pass}_ms="*) say "FAIL A. forward's pass $pass is counted as the chapter's: $line" ;; esac
done
awk -v f="${fwd:-0}" -v a="$alone" 'BEGIN { exit !(f > 0 && f >= 0.1 * a) }' &&
  say "ok   A. the bench line's forward ($fwd ms) is at least 0.1 x forward alone ($alone ms)" ||
  say "FAIL A. the bench line's forward is ${fwd:-missing} ms against $alone ms alone"

# B. "... | 5.43 ms (184 fps; a 1.00, b 4.40) [clock] | compare: forward 2.10 ms | ..." -> "own fwd sum n"
titles=$(sed -n 's/.*window: .* | \([0-9.]*\) ms ([0-9]* fps; \([^)]*\)) \[[^]]*\] | compare: forward \([0-9.]*\) ms |.*/\1 \3 \2/p' "$tmp/err" |
  awk '{ own = $1; fwd = $2; $1 = $2 = ""; n = split($0, p, ", "); sum = 0
         for (i = 1; i <= n; i++) { k = split(p[i], w, " "); sum += w[k] }
         print own, fwd, sum, n }')
[ -n "$titles" ] || say "FAIL B. no title with a compare figure in --verbose's log"
while read -r own f sum n; do
  [ -n "$own" ] || continue
  awk -v o="$own" -v f="$f" -v s="$sum" -v n="$n" -v a="$alone" \
    'BEGIN { exit !(f >= 0.1 * a && s >= 0.75 * o - 0.02 && s <= o + 0.005 * (n + 1)) }' &&
    say "ok   B. title: the chapter $own ms (its $n passes add up to $sum), forward $f ms" ||
    say "FAIL B. title: the chapter $own ms with passes adding up to $sum, forward $f ms (alone $alone)"
done <<<"$titles"
# Each overlay print against the title logged before it (stdout and stderr interleave by frame: the
# title is logged at the end of a frame, the overlay after it; both are read in frame order here).
grep -n '' "$tmp/err" | sed -n 's/^\([0-9]*\):.*window: .* | \([0-9.]*\) ms (.*compare: forward \([0-9.]*\) ms.*/\2 \3/p' >"$tmp/t"
mapfile -t seen < <(sed -n 's/^overlay: compare split: forward \([0-9.]*\) ms (left) | [a-z-]* \([0-9.]*\) ms (right)/\2 \1/p' "$tmp/out")
[ ${#seen[@]} -eq 2 ] || say "FAIL B. the overlay printed ${#seen[@]} compare lines, not 2"
for s in "${seen[@]}"; do
  grep -qx "$s" "$tmp/t" && say "ok   B. the overlay's figures ($s) are a title's" ||
    say "FAIL B. the overlay showed '$s' (own, forward), no title did: $(tr '\n' ';' <"$tmp/t")"
done
exit $fail
