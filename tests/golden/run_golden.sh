#!/usr/bin/env bash
# run_golden.sh IMGDIFF OUTDIR NAME GOLDEN TOLERANCE MAX_FRACTION -- COMMAND...
# Renders COMMAND's screenshot into OUTDIR/NAME.png and compares it with GOLDEN.
# Exit 77 (skip) when the command could not get a GL context. TOLERANCE and MAX_FRACTION may be
# "LLVMPIPE,OTHER" (tests/golden/renderer_bounds.sh).
set -u
imgdiff=$1 outdir=$2 name=$3 golden=$4 tol=$5 frac=$6
shift 6
[ "$1" = "--" ] && shift
. "$(dirname "$0")/renderer_bounds.sh"
tol=$(bound_for "$tol" "$1") frac=$(bound_for "$frac" "$1")
mkdir -p "$outdir"
actual="$outdir/$name.png"
rm -f "$actual" "$outdir/$name.diff.png"
"$@" --screenshot "$actual"
rc=$?
if [ $rc -eq 77 ]; then
  echo "skip: no GL context"
  exit 77
fi
if [ $rc -ne 0 ]; then
  echo "FAIL: '$*' exited with $rc"
  exit 1
fi
if [ ! -f "$golden" ]; then
  echo "FAIL: no golden image $golden (render it with: cmake --build build --target update-goldens)"
  exit 1
fi
"$imgdiff" --tolerance "$tol" --max-fraction "$frac" --heatmap-on-fail "$outdir/$name.diff.png" "$golden" "$actual"
rc=$?
[ $rc -ne 0 ] && echo "actual: $actual  diff heat map: $outdir/$name.diff.png"
exit $rc
