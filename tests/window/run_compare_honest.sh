#!/usr/bin/env bash
# run_compare_honest.sh CHAPTER [ARGS...] - compare mode never reports forward at 0 ms for a frame that
# drew it, nor a 0 it did not measure, with a busy loop taking a core beside it (the load under which a
# learner once saw "forward 0.00 ms"):
#   1. --script: H, then M pressed, pressed again and again (split, difference, off, split), the
#      overlay printed at each of those frames and the next: each compare line gives forward's time
#      above 0.00 ms, or says forward was not timed yet (the figures the overlay averages may predate M;
#      GPU queries are read a frame late), on both frame clocks
#   2. --compare split --bench: compare_forward_ms above 0, every timed frame having drawn forward
# No figure is checked against another: only "not zero when a frame was drawn".
# Skips (77) without a GL context.
set -u
bin=$1
shift
tmp=$(mktemp -d)
( while :; do :; done ) &
busy=$!
trap 'kill "$busy" 2>/dev/null; rm -rf "$tmp"' EXIT
fail=0
say() { echo "$1"; case $1 in FAIL*) fail=1 ;; esac; }
common=(--headless --size 160x120 "$@")

printf '%s\n' "0 key H" "2 key M" "2 overlay" "3 overlay" "4 key M" "4 overlay" "5 key M" "5 overlay" \
  "6 key M" "6 overlay" "7 overlay" "7 quit" >"$tmp/script"
for clock in cpu gpu; do # gpu: the query path, read one frame late (its figures mean nothing on llvmpipe)
  COURSE_FRAME_CLOCK=$clock "$bin" "${common[@]}" --paused --script "$tmp/script" >"$tmp/out" 2>"$tmp/err"
  rc=$?
  [ $rc -eq 77 ] && { echo "skip: no GL context"; exit 77; }
  [ $rc -eq 0 ] || { echo "FAIL 1. --script ($clock clock): exit $rc: $(head -2 "$tmp/err")"; exit 1; }
  lines=$(grep '^overlay: compare ' "$tmp/out")
  count=$(grep -c . <<<"$lines")
  zero=$(grep -v 'forward not timed yet' <<<"$lines" | grep -v 'forward [0-9]*\.[0-9]*[1-9][0-9]* ms\|forward [1-9][0-9]*\.[0-9]* ms')
  if [ "$count" -eq 5 ] && [ -z "$zero" ]; then
    say "ok   1. $clock clock: $count compare lines, each with forward's time above 0 or 'not timed yet'"
  else
    say "FAIL 1. $clock clock: $count compare lines (want 5); reporting 0: ${zero:-none}"
  fi
done

"$bin" "${common[@]}" --frames 3 --warmup 1 --compare split --bench >"$tmp/bench" 2>"$tmp/err"
rc=$?
[ $rc -eq 0 ] || { echo "FAIL 2. --bench: exit $rc: $(head -2 "$tmp/err")"; exit 1; }
fwd=$(sed -n 's/^bench:.* compare_forward_ms=\([^ ]*\).*/\1/p' "$tmp/bench")
awk -v f="${fwd:-0}" 'BEGIN { exit !(f > 0) }' && say "ok   2. the bench line's compare_forward_ms is $fwd" ||
  say "FAIL 2. compare_forward_ms is '${fwd:-missing}' though every frame drew forward"
exit $fail
