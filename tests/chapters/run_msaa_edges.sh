#!/usr/bin/env bash
# run_msaa_edges.sh CHAPTER OUTDIR SCENE - chapter 13's edge mask and anti-aliasing on one flat quad:
# renders it with 1 sample, with 4 and in the edges view, then tests/chapters/msaa_edges.py checks them.
set -u
chapter=$1 outdir=$2 scene=$3
mkdir -p "$outdir"
args=(--headless --size 320x240 --frames 1 --gl-debug --scene "$scene")
for run in "one|--samples 1" "msaa|--samples 4" "edges|--samples 4 --view edges"; do
  name=${run%%|*}
  read -r -a extra <<<"${run#*|}"
  "$chapter" "${args[@]}" "${extra[@]}" --screenshot "$outdir/$name.png" >/dev/null
  rc=$?
  if [ $rc -eq 77 ]; then echo "skip: no GL context"; exit 77; fi
  if [ $rc -ne 0 ]; then echo "FAIL: $chapter ${extra[*]} exited with $rc"; exit 1; fi
done
/usr/bin/python3 "$(dirname "$0")/msaa_edges.py" "$outdir/one.png" "$outdir/msaa.png" "$outdir/edges.png"
