#!/usr/bin/env bash
# run_agreement.sh IMGDIFF OUTDIR NAME TOLERANCE MAX_FRACTION -- COMMAND_A... -- COMMAND_B...
# Renders the same frame with two commands and compares them: the course's claims
# ("deferred matches forward", "the pre-pass changes nothing") as checks. TOLERANCE and
# MAX_FRACTION may be "LLVMPIPE,OTHER" (tests/golden/renderer_bounds.sh).
set -u
imgdiff=$1 outdir=$2 name=$3 tol=$4 frac=$5
shift 5
[ "$1" = "--" ] && shift
a=() b=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do a+=("$1"); shift; done
[ $# -gt 0 ] && shift
b=("$@")
. "$(dirname "$0")/renderer_bounds.sh"
tol=$(bound_for "$tol" "${a[0]}") frac=$(bound_for "$frac" "${a[0]}")
mkdir -p "$outdir"
for side in a b; do
  if [ $side = a ]; then cmd=("${a[@]}"); else cmd=("${b[@]}"); fi
  out="$outdir/$name.$side.png"
  rm -f "$out"
  "${cmd[@]}" --screenshot "$out"
  rc=$?
  if [ $rc -eq 77 ]; then echo "skip: no GL context"; exit 77; fi
  if [ $rc -ne 0 ]; then echo "FAIL: '${cmd[*]}' exited with $rc"; exit 1; fi
done
"$imgdiff" --tolerance "$tol" --max-fraction "$frac" --heatmap-on-fail "$outdir/$name.diff.png" \
  "$outdir/$name.a.png" "$outdir/$name.b.png"
