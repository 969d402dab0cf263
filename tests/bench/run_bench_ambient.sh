#!/usr/bin/env bash
# run_bench_ambient.sh BENCH OUTDIR - the benchmark's ambient rows (--ambient-sweep only, at --quick's
# size): OUTDIR/bench_ambient.csv has the header and one row per scene and chapter (2 x 3), with a
# finite frame and lighting time in every row, an SSAO time in chapter 17's and memory in 17's and
# 19's (at least 1 MiB: a probe at the default 128^2 per face takes 2). Then the errors against the exact references (tools/bench/bench_ambient_error.h): both
# sections in bench_ambient.md; bench_ambient_ssao.csv, one row per setting (4, 16, 64 directions x
# blur 0, 2 at radius 0.5), each timed, with finite errors in A (0 to 1) over some pixels;
# bench_ambient_ibl.csv, roughness 0, 0.25 ... 1, each error a finite number. The shape only, never
# the timings (they depend on the machine), nor the errors' size (hard.ssao_reference and
# hard.ibl_reference bound those). Run alone, the part writes its four files only: the main sweep's
# files seeded in OUTDIR stay as they were, the plan names the part (not a sweep), the last line
# names those four files, and no difference prints with two signs (tests/bench/partial_run.sh).
set -u
. "$(dirname "$0")/partial_run.sh"
bench=$1 out=$2
rm -rf "$out"
mkdir -p "$out"
partial_seed "$out"
"$bench" --quick --ambient-sweep only --quiet --out "$out" >"$out.stdout" 2>"$out.stderr"
rc=$?
[ $rc -eq 77 ] && exit 77
[ $rc -ne 0 ] && { echo "FAIL: bench exited with $rc"; cat "$out.stderr"; exit 1; }
partial_check "$out" "$out.stdout" "$out.stderr" \
    bench_ambient.md bench_ambient.csv bench_ambient_ssao.csv bench_ambient_ibl.csv || exit 1
csv="$out/bench_ambient.csv"
[ -f "$csv" ] && [ -f "$out/bench_ambient.md" ] || { echo "FAIL: no $csv or bench_ambient.md"; exit 1; }
awk -F, 'NR == 1 { if ($1 != "scene" || NF != 14) { print "FAIL: header: " $0; bad = 1 }; next }
         { rows++
           if ($6 == "" || $11 == "" || $6 + 0 <= 0 || $11 + 0 <= 0) { print "FAIL: no frame or lighting time: " $0; bad = 1 }
           if ($2 == "17_ssao" && ($9 == "" || $9 + 0 <= 0 || $14 + 0 <= 0)) { print "FAIL: 17 without SSAO time or memory: " $0; bad = 1 }
           if ($2 == "19_image_based_light" && $14 + 0 < 1048576) { print "FAIL: 19 without the memory of its probes: " $0; bad = 1 } }
         END { if (rows != 6) { print "FAIL: " rows " rows, expected 6"; bad = 1 }
               if (!bad) print "ok: 6 rows"; exit bad }' "$csv" || exit 1
for section in "SSAO against traced occlusion" "Split sum against Monte Carlo"; do
  grep -q "^## $section\$" "$out/bench_ambient.md" || { echo "FAIL: no section '$section' in bench_ambient.md"; exit 1; }
done
num='^[0-9]+([.][0-9]+)?$'
awk -F, -v num="$num" 'NR == 1 { if ($1 != "scene" || NF != 17) { print "FAIL: SSAO header: " $0; bad = 1 }; next }
         { rows++
           for (i = 2; i <= 17; i++) if (i != 9 && $i !~ num) { print "FAIL: field " i " not a finite number: " $0; bad = 1 }
           if ($7 + 0 <= 0 || $8 + 0 <= 0) { print "FAIL: no frame or SSAO time: " $0; bad = 1 }
           if (($3 > 0) != ($9 ~ num && $9 + 0 > 0)) { print "FAIL: a blur time without a blur, or none with one: " $0; bad = 1 }
           if ($14 + 0 < 100 || $15 + 0 > 1 || $16 + 0 > 1 || $17 + 0 > 100) { print "FAIL: errors out of range: " $0; bad = 1 } }
         END { if (rows != 6) { print "FAIL: " rows " SSAO rows, expected 6"; bad = 1 }
               if (!bad) print "ok: 6 SSAO settings with time and error"; exit bad }' "$out/bench_ambient_ssao.csv" || exit 1
awk -F, -v num="$num" 'NR == 1 { if ($1 != "scene" || NF != 7) { print "FAIL: IBL header: " $0; bad = 1 }; next }
         { if ($2 + 0 != rows * 0.25) { print "FAIL: roughness " $2 ", expected " rows * 0.25; bad = 1 }
           rows++
           for (i = 2; i <= 7; i++) if ($i !~ num) { print "FAIL: field " i " not a finite number: " $0; bad = 1 } }
         END { if (rows != 5) { print "FAIL: " rows " roughness rows, expected 5"; bad = 1 }
               if (!bad) print "ok: the split sum error at 5 roughnesses"; exit bad }' "$out/bench_ambient_ibl.csv"
