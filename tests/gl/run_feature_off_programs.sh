#!/usr/bin/env bash
# run_feature_off_programs.sh CH14 CH17 CH19 SCENE - a feature that is off is compiled out: chapter 14
# with --shadows 0 or on a scene whose lights are all `shadow off`, chapter 17 with --ssao off and
# chapter 19 with --ibl off build their lighting programs without SHADOWS, AMBIENT_OCCLUSION and
# IMAGE_BASED_LIGHT (the --bench 'programs:' line lists every program a run compiled), and with them
# on build them with (so the check can fail). SCENE: the default scene, copied with `shadow off` on
# every light into OUTDIR. Skips (77) without a GL context.
set -u
ch14=$1 ch17=$2 ch19=$3 scene=$4 outdir=$5
fail=0
say() { echo "$1"; case $1 in FAIL*) fail=1 ;; esac; }
# lighting CHAPTER ARGS...: the deferred lighting programs' entries of the run's 'programs:' line
lighting() {
  local out rc
  out=$("$@" --headless --size 96x72 --bench --frames 1 --warmup 0 2>&1)
  rc=$?
  if [ "$rc" -eq 77 ]; then echo "skip: no GL context"; exit 77; fi
  [ "$rc" -eq 0 ] || { say "FAIL $*: exit $rc"; return; }
  grep '^programs:' <<<"$out" | tr ' ' '\n' | grep 'clustered_deferred.frag' | tr '\n' ' '
}
expect() { # WHAT PROGRAMS PATTERN yes|no
  if [ -z "$2" ]; then say "FAIL $1: no lighting program listed"; return; fi
  if grep -q "$3" <<<"$2"; then [ "$4" = yes ] && say "ok   $1: $2" || say "FAIL $1: $2 has $3"
  else [ "$4" = no ] && say "ok   $1: $2" || say "FAIL $1: $2 lacks $3"; fi
}
mkdir -p "$outdir"
unshadowed=$outdir/feature_off_unshadowed.scene
sed 's/^\(light .*\)$/\1 shadow off/' "$scene" >"$unshadowed"
grep -q 'shadow off' "$unshadowed" || say "FAIL could not write a scene of unshadowed lights"
expect "14 --shadows 0" "$(lighting "$ch14" --shadows 0)" SHADOWS no
expect "14, every light shadow off" "$(lighting "$ch14" --scene "$unshadowed")" SHADOWS no
expect "14" "$(lighting "$ch14")" SHADOWS yes
expect "17 --ssao off" "$(lighting "$ch17" --ssao off)" AMBIENT_OCCLUSION no
expect "17 --ssao on" "$(lighting "$ch17" --ssao on)" AMBIENT_OCCLUSION yes
expect "19 --ibl off" "$(lighting "$ch19" --ibl off)" IMAGE_BASED_LIGHT no
expect "19 --ibl off --ssao off" "$(lighting "$ch19" --ibl off)" AMBIENT_OCCLUSION no
expect "19 --ibl on" "$(lighting "$ch19" --ibl on)" IMAGE_BASED_LIGHT yes
exit "$fail"
