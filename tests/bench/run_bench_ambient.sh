#!/usr/bin/env bash
# run_bench_ambient.sh BENCH OUTDIR - the benchmark's ambient rows (--ambient-sweep only, at --quick's
# size): OUTDIR/bench_ambient.csv has the header and one row per scene and chapter (2 x 3), with a
# finite frame and lighting time in every row, an SSAO time in chapter 17's and memory in 17's and
# 19's. The shape only, never the timings (they depend on the machine).
set -u
bench=$1 out=$2
rm -rf "$out"
"$bench" --quick --ambient-sweep only --no-plots --quiet --out "$out"
rc=$?
[ $rc -eq 77 ] && exit 77
[ $rc -ne 0 ] && { echo "FAIL: bench exited with $rc"; exit 1; }
csv="$out/bench_ambient.csv"
[ -f "$csv" ] && [ -f "$out/bench_ambient.md" ] || { echo "FAIL: no $csv or bench_ambient.md"; exit 1; }
awk -F, 'NR == 1 { if ($1 != "scene" || NF != 14) { print "FAIL: header: " $0; bad = 1 }; next }
         { rows++
           if ($6 == "" || $11 == "" || $6 + 0 <= 0 || $11 + 0 <= 0) { print "FAIL: no frame or lighting time: " $0; bad = 1 }
           if ($2 == "17_ssao" && ($9 == "" || $9 + 0 <= 0 || $14 + 0 <= 0)) { print "FAIL: 17 without SSAO time or memory: " $0; bad = 1 }
           if ($2 == "19_image_based_light" && $14 + 0 <= 0) { print "FAIL: 19 without memory: " $0; bad = 1 } }
         END { if (rows != 6) { print "FAIL: " rows " rows, expected 6"; bad = 1 }
               if (!bad) print "ok: 6 rows"; exit bad }' "$csv"
