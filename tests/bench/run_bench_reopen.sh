#!/usr/bin/env bash
# run_bench_reopen.sh BENCH OUTDIR - every renderer the benchmark drives on a Blinn-Phong scene, then on
# the PBR teapots: the material model changes, so each chapter is closed and opened again in the same
# process. A chapter that kept a freed pointer or a stale size from its first run (chapter 10's tile
# arrays did) corrupts the heap or fails a read-back here. Passes when the run ends cleanly and every
# renderer has its PBR row. The ambient sweep comes after, and opens chapter 11 again itself (it
# failed while the main sweep's chapters were left open).
set -u
bench=$1 out=$2
renderers=forward,forward-plus,deferred-fullscreen,deferred-volumes,deferred-stencil,deferred-tiled,deferred-clustered
rm -rf "$out"
"$bench" --scenes default --lights 1 --cutoffs none --renderers "$renderers" --pbr-scenes pbr_teapots \
  --pbr-renderers "$renderers" --size 96x96 --frames 1 --warmup 0 --no-plots --out "$out" --storage off \
  --gbuffer-sweep off --ambient-sweep on
rc=$?
[ $rc -eq 77 ] && exit 77
[ $rc -eq 0 ] || { echo "FAIL: bench exited with $rc"; exit 1; }
rows=$(grep -c '^pbr,' "$out/bench.csv")
[ "$rows" -eq 7 ] || { echo "FAIL: $rows PBR rows in $out/bench.csv, expected 7"; head -3 "$out/bench.csv"; exit 1; }
echo "ok: 7 renderers opened twice, 7 PBR rows"
