#!/usr/bin/env bash
# run_shadow_keys.sh IMGDIFF OUTDIR CHAPTER_14 CHAPTER_11 [ARGS...] - chapter 14's key and overlay,
# driven headless by a --script (the window's events, frame by frame):
#   1. K turns shadows off: the picture is chapter 11's, byte for byte, drawn by the lighting programs
#      built without SHADOWS (off costs nothing); K again: chapter 14's again, by the SHADOWS programs
#   2. the overlay's lines: on, the lights shadowed and dropped and the tiles drawn (all of them in the
#      first frame, none in a later one: cached); off after K; the passes line times the shadow pass
#      as its own pass ("shadows")
# Skips (77) without a GL context; never passes without checking.
set -u
imgdiff=$1 outdir=$2 ch14=$3 ch11=$4
shift 4
args=(--headless --size 160x120 "$@")
mkdir -p "$outdir"
out="$outdir/shadow_keys"
rm -f "$out".*
fail=0
say() { echo "$1"; case $1 in FAIL*) fail=1 ;; esac; }
same() { # same EXPECTED ACTUAL WHAT: byte for byte
  if "$imgdiff" --quiet --tolerance 0 --max-fraction 0 "$1" "$2" >"$out.diff" 2>&1; then say "ok   $3"
  else say "FAIL $3: $(tail -1 "$out.diff") ($2)"; fi
}
cat >"$out.script" <<SCRIPT
0 overlay
0 screenshot $out.on.png
1 overlay
2 key K
2 screenshot $out.off.png
2 overlay
3 key K
3 screenshot $out.on-again.png
3 quit
SCRIPT
"$ch14" "${args[@]}" --script "$out.script" >"$out.stdout" 2>"$out.stderr"
rc=$?
if [ "$rc" -eq 77 ]; then echo "skip: no GL context: $(head -1 "$out.stderr")"; exit 77; fi
[ "$rc" -eq 0 ] || { echo "FAIL 14 --script: exit $rc: $(head -3 "$out.stderr")"; exit 1; }
"$ch14" "${args[@]}" --screenshot "$out.14.png" 2>/dev/null || say "FAIL chapter 14's headless picture"
"$ch11" "${args[@]}" --screenshot "$out.11.png" 2>/dev/null || say "FAIL chapter 11's headless picture"
"$imgdiff" --quiet --tolerance 0 --max-fraction 0 "$out.11.png" "$out.14.png" >/dev/null 2>&1 &&
  say "FAIL chapters 11 and 14 draw the same picture here: the test below proves nothing"
same "$out.14.png" "$out.on.png" "K: before it, chapter 14's picture"
same "$out.11.png" "$out.off.png" "K: shadows off, chapter 11's picture"
same "$out.14.png" "$out.on-again.png" "K again: chapter 14's picture again"
said=$(grep -o 'lighting programs built with[a-z]* SHADOWS' "$out.stderr" | tr '\n' '|')
want='lighting programs built with SHADOWS|lighting programs built without SHADOWS|lighting programs built with SHADOWS|'
[ "$said" = "$want" ] && say "ok   the programs switch: with SHADOWS, without after K, with after K again" ||
  say "FAIL the programs' switches were '$said', want '$want'"

# The overlay, frame by frame: "overlay: shadows on (K): N lights shadowed, D dropped, ..." and
# "overlay: shadow tiles T, drawn K (...)".
mapfile -t shadowed < <(sed -n 's/^overlay: shadows on (K): \([0-9]*\) lights shadowed, \([0-9]*\) dropped.*/\1 \2/p' "$out.stdout")
mapfile -t drawn < <(sed -n 's/^overlay: shadow tiles \([0-9]*\), drawn \([0-9]*\) .*/\1 \2/p' "$out.stdout")
read -r n dropped <<<"${shadowed[0]:-0 -1}"
read -r tiles first <<<"${drawn[0]:-0 -1}"
read -r _ later <<<"${drawn[1]:-0 -1}"
if [ "${#shadowed[@]}" -eq 2 ] && [ "$n" -gt 0 ] && [ "$dropped" -eq 0 ] && [ "$tiles" -gt 0 ] && [ "$first" -eq "$tiles" ] &&
   [ "$later" -eq 0 ]; then
  say "ok   overlay: $n lights shadowed, $dropped dropped, $tiles tiles: all drawn in the first frame, none in the next"
else
  say "FAIL overlay: shadowed/dropped '${shadowed[*]}', tiles/drawn '${drawn[*]}' (want N>0 0 twice; T T, then T 0)"
fi
grep -q '^overlay: shadows off (K)' "$out.stdout" && say "ok   overlay: K says shadows off" ||
  say "FAIL overlay: no 'shadows off' line after K"
grep -q '^overlay: passes (ms):.* shadows [0-9.]*,' "$out.stdout" && say "ok   overlay: the shadow pass timed on its own" ||
  say "FAIL overlay: no 'shadows' pass on the passes line"
exit "$fail"
