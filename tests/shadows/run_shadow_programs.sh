#!/usr/bin/env bash
# run_shadow_programs.sh IMGDIFF OUTDIR CH14 CH11 - chapter 14 runs its SHADOWS programs only while a
# light is shadowed (docs/14_shadows.md, "Shadows off cost nothing"):
#   1. K in the window (a --script): the lighting programs switch to the ones built without SHADOWS and
#      the picture is chapter 11's, byte for byte; K again: the SHADOWS programs and the shadowed picture
#   2. --shadows 0: no program of the frame is built with SHADOWS (the --bench 'programs:' line lists
#      every program the run compiled; only the window's forward program, built at start, has it)
#   3. a scene whose lights are all `shadow off`: the same
# Skips (77) without a GL context; never passes without checking.
set -u
imgdiff=$1 outdir=$2 ch14=$3 ch11=$4
mkdir -p "$outdir"
out="$outdir/14_shadow_programs"
rm -f "$out".*
args=(--headless --size 160x120)
fail=0
say() { echo "$1"; case $1 in FAIL*) fail=1 ;; esac; }
same() { # same EXPECTED ACTUAL WHAT: byte for byte
  if "$imgdiff" --quiet --tolerance 0 --max-fraction 0 "$1" "$2" >"$out.diff" 2>&1; then say "ok   $3"
  else say "FAIL $3: $(tail -1 "$out.diff") ($2)"; fi
}
cat >"$out.script" <<SCRIPT
0 screenshot $out.on.png
1 key K
1 screenshot $out.off.png
2 key K
2 screenshot $out.on-again.png
2 quit
SCRIPT
"$ch14" "${args[@]}" --script "$out.script" >"$out.stdout" 2>"$out.stderr"
rc=$?
if [ "$rc" -eq 77 ]; then echo "skip: no GL context: $(head -1 "$out.stderr")"; exit 77; fi
[ "$rc" -eq 0 ] || { echo "FAIL 14_shadows --script: exit $rc: $(head -3 "$out.stderr")"; exit 1; }
"$ch11" "${args[@]}" --screenshot "$out.11.png" >/dev/null 2>&1 || say "FAIL chapter 11's picture"
"$imgdiff" --quiet --tolerance 0 --max-fraction 0 "$out.11.png" "$out.on.png" >/dev/null 2>&1 &&
  say "FAIL chapter 14 draws chapter 11's picture with its shadows on: the test below proves nothing"
same "$out.11.png" "$out.off.png" "K: shadows off, chapter 11's picture"
same "$out.on.png" "$out.on-again.png" "K again: the shadowed picture again"
# the switches, in order, as the chapter says them
said=$(grep -o 'lighting programs built with[a-z]* SHADOWS' "$out.stderr" | tr '\n' '|')
want='lighting programs built with SHADOWS|lighting programs built without SHADOWS|lighting programs built with SHADOWS|'
[ "$said" = "$want" ] && say "ok   the programs switch: with SHADOWS, without after K, with after K again" ||
  say "FAIL the programs' switches were '$said', want '$want'"

# --shadows 0, and a scene of unshadowed lights: the frame's programs are all built without SHADOWS
sed 's/^\(light .*\)$/\1 shadow off/' assets/scenes/default.scene >"$out.off.scene"
grep -q 'shadow off' "$out.off.scene" || say "FAIL could not write a scene of unshadowed lights"
for run in "--shadows 0" "--scene $out.off.scene"; do
  # shellcheck disable=SC2086 # run is two words on purpose
  line=$("$ch14" "${args[@]}" $run --bench --frames 2 2>/dev/null | grep '^programs:')
  [ -n "$line" ] || { say "FAIL $run: no 'programs:' line"; continue; }
  shadowed=$(tr ' ' '\n' <<<"$line" | grep 'SHADOWS' | grep -v -e '^forward.vert+forward.frag' -e 'shadow_visibility' || true)
  lit=$(tr ' ' '\n' <<<"$line" | grep -c 'clustered_deferred.frag')
  if [ -z "$shadowed" ] && [ "$lit" -ge 1 ]; then say "ok   $run: the lighting pass's programs have no SHADOWS"
  else say "FAIL $run: programs built with SHADOWS: '$shadowed' (lighting programs: $lit)"; fi
done
"$ch14" "${args[@]}" --shadows 0 --screenshot "$out.none.png" >/dev/null 2>&1
same "$out.11.png" "$out.none.png" "--shadows 0: chapter 11's picture"
exit "$fail"
