#!/usr/bin/env bash
# run_bench_quick.sh BENCH OUT_DIR - run `bench --quick` and check the shape of what it wrote:
# the files exist, the CSV has its header and one row per (case, renderer), every numeric cell is a
# finite number or NA, and measured rows have positive times. Timings themselves are never checked.
# The skip predictor is switched off (--max-frame-ms and --case-budget-ms far above anything a
# 160x160 frame takes): a loaded machine would otherwise skip a case or give it fewer frames, and
# what the run covers would depend on the load; so every row must be measured with all 3 frames.
# Exit 77 (no GL context) passes through as a skip.
set -u
. "$(dirname "$0")/../lib/args.sh"
args_expect 2 "$@"
bench=$1
out=$2
args_fresh_dir "$out"
"$bench" --quick --max-frame-ms 1e9 --case-budget-ms 1e9 --out "$out" >"$out.stdout" 2>"$out.stderr"
rc=$?
if [ "$rc" -eq 77 ]; then
    echo "skip: no GL context"
    exit 77
fi
if [ "$rc" -ne 0 ]; then
    echo "FAIL: bench --quick exited $rc"; cat "$out.stderr"; exit 1
fi

fail=0
for f in bench.csv bench.md time_vs_lights.png speed_vs_error.png; do
    if [ ! -s "$out/$f" ]; then echo "FAIL: $out/$f missing or empty"; fail=1; fi
done
# Atomic writes leave no temporary files behind.
if ls "$out"/*.tmp >/dev/null 2>&1; then echo "FAIL: temporary files left in $out"; fail=1; fi
for f in time_vs_lights.png speed_vs_error.png; do
    if [ -s "$out/$f" ] && [ "$(head -c 4 "$out/$f" | tail -c 3)" != "PNG" ]; then
        echo "FAIL: $out/$f is not a PNG"; fail=1
    fi
done
[ "$fail" -eq 0 ] || exit 1

# The CSV: the stable header, then (3 light counts x R renderers) + (3 cut-offs x (R - 1)) rows, the
# naive forward renderer being left out of the cut-off sweep (--quick: 1,16,64 lights; 2,5,16/256),
# then the PBR rows: pbr_teapots and gltf_engine, each with its own lights, by forward, forward-plus
# and deferred-clustered. gltf_engine imports a sample of Debian's assimp-testmodels: without the
# package its rows say not_loaded, and only then.
engine=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
have_engine=0; [ -f "$engine" ] && have_engine=1
awk -F, -v have_engine="$have_engine" '
NR == 1 {
    want = "sweep,scene,renderer,light_set,lights,active_lights,cutoff_256,width,height,frames,warmup," \
           "median_ms,min_ms,max_ms,fps,status,shaded_pixels,covered_pixels,ideal_pairs,light_evals," \
           "work_ratio,gbuffer_bytes,gbuffer_naive_bytes,max_abs_8bit,mean_abs_8bit,psnr_8bit,max_abs_hdr," \
           "mean_abs_hdr,psnr_hdr,light_lists_ms,depth_prepass_ms,shading_ms,geometry_ms,lighting_ms," \
           "present_ms,pass_clock,note"
    if ($0 != want) { print "FAIL: header is\n  " $0 "\nwanted\n  " want; bad = 1 }
    ncol = NF; next
}
{
    rows++
    if (NF != ncol) { printf "FAIL: row %d has %d fields, header %d\n", NR, NF, ncol; bad = 1 }
    if ($1 == "lights") lights_rows++; else if ($1 == "cutoff") cutoff_rows++;
    else if ($1 == "pbr") { pbr_rows++; pbr_scenes[$2] = 1 }
    else { printf "FAIL: row %d: sweep %s\n", NR, $1; bad = 1 }
    if ($1 != "pbr") renderers[$3] = 1
    if ($1 == "pbr" && $16 == "not_loaded") {
        if ($2 != "gltf_engine" || have_engine) { printf "FAIL: row %d: %s not loaded\n", NR, $2; bad = 1 }
        next
    }
    # the PBR rows: the scene'"'"'s own lights (80 teapots, 32 engine), a 16-byte layout for the deferred
    # renderer, and its error against the exact picture that of forward (a G-buffer that cannot hold the
    # materials would shade them as Blinn-Phong: far more)
    if ($1 == "pbr") {
        if ($4 != "scene" || ($2 == "pbr_teapots" && $5 != 80) || ($2 == "gltf_engine" && $5 != 32)) {
            printf "FAIL: row %d: %s with %s lights %s\n", NR, $2, $4, $5; bad = 1
        }
        if ($3 == "deferred-clustered" && $22 != 16) { printf "FAIL: row %d: G-buffer %s bytes\n", NR, $22; bad = 1 }
        pbr_error[$2 "," $3] = $25
    }
    # numeric columns 5..15 and 17..29: a finite number or NA
    for (i = 5; i <= 29; i++) {
        if (i == 16) continue
        if ($i == "NA") continue
        if ($i !~ /^-?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?$/) {
            printf "FAIL: row %d column %d is \"%s\", not a finite number\n", NR, i, $i; bad = 1
        }
    }
    # nothing is predicted slow (see the top): every case drawn, with the 3 frames of --quick
    if ($16 != "measured" || $10 != 3) {
        printf "FAIL: row %d status \"%s\", %s frames: want measured, 3\n", NR, $16, $10; bad = 1
    }
    if ($16 == "measured" && !($12 > 0 && $13 > 0 && $14 >= $13 && $12 >= $13 && $12 <= $14)) {
        printf "FAIL: row %d times not ordered min <= median <= max > 0: %s %s %s\n", NR, $13, $12, $14; bad = 1
    }
    if ($16 == "measured" && $17 == "NA") { printf "FAIL: row %d has no shaded pixel count\n", NR; bad = 1 }
    # the ideal count never exceeds covered pixels x active lights, and every renderer shades a pixel at least
    # as often as the ideal count needs only when lights are few (1 light: evaluations >= 0.9 x ideal)
    if ($19 != "NA" && $18 != "NA" && $19 > $18 * $6) { printf "FAIL: row %d ideal > covered x lights\n", NR; bad = 1 }
    if ($5 == 1 && $20 != "NA" && $20 < 0.9 * $19) { printf "FAIL: row %d evaluations %s << ideal %s\n", NR, $20, $19; bad = 1 }
    if ($26 != "NA" && ($26 < 0 || $26 > 100)) { printf "FAIL: row %d PSNR %s\n", NR, $26; bad = 1 }
}
END {
    r = 0; for (k in renderers) r++
    if (r < 3) { printf "FAIL: only %d renderers\n", r; bad = 1 }
    if (lights_rows != 3 * r) { printf "FAIL: %d light-sweep rows, want %d\n", lights_rows, 3 * r; bad = 1 }
    if (cutoff_rows != 3 * (r - 1)) { printf "FAIL: %d cut-off rows, want %d\n", cutoff_rows, 3 * (r - 1); bad = 1 }
    if (pbr_rows != 6 || !("pbr_teapots" in pbr_scenes) || !("gltf_engine" in pbr_scenes)) {
        printf "FAIL: %d PBR rows, want pbr_teapots and gltf_engine by 3 renderers\n", pbr_rows; bad = 1
    }
    for (k in pbr_error) {
        split(k, sr, ","); f = pbr_error[sr[1] ",forward"]
        if (sr[2] != "forward" && (pbr_error[k] - f > 0.5 || f - pbr_error[k] > 0.5)) {
            printf "FAIL: %s: mean 8-bit error %s, forward %s\n", k, pbr_error[k], f; bad = 1
        }
    }
    if (!bad) printf "ok: %d rows, %d renderers\n", rows, r
    exit bad
}' "$out/bench.csv" || exit 1

# The report has its sections.
for section in "## Targets" "## Crossover" "## Median ms per frame" "## Lighting work" "## Error against" \
               "## Speed against error" "## Metallic-roughness scenes"; do
    grep -q "^$section" "$out/bench.md" || { echo "FAIL: bench.md lacks '$section'"; exit 1; }
done
# The quick sweep has no target case: the Targets section says so instead of an empty table.
awk '/^## Targets/ { t = 1; next } /^## / { t = 0 } t && /^\|---/ { getline; if ($0 !~ /^\| /) bad = 1 }
     t && /holds none of the targets/ { said = 1 } END { exit bad || !said }' "$out/bench.md" ||
    { echo "FAIL: the quick run's Targets section is an empty table or says nothing"; exit 1; }
# The plots: each renderer its own colour and point type, the same pair in both plots.
styles=$(grep -o "with linespoints lc rgb '[^']*' pt [0-9]* title '[^']*'" "$out/bench_plots.gp" |
         sed "s/with linespoints lc rgb '\([^']*\)' pt \([0-9]*\) title '\([^']*\)'/\3 \1-\2/" | sort -u)
renderers=$(echo "$styles" | awk '{ print $1 }' | sort -u | wc -l)
pairs=$(echo "$styles" | awk '{ print $2 }' | sort -u | wc -l)
lines=$(echo "$styles" | wc -l)
if [ "$renderers" -lt 9 ] || [ "$pairs" -ne "$renderers" ] || [ "$lines" -ne "$renderers" ]; then
    echo "FAIL: the plots' styles (renderer colour-point): $(echo $styles)"; exit 1
fi
# The start says what the run will do and where its results go; --cutoffs none drops the cut-off
# section and its plot, --pbr-scenes none the PBR rows and their section; with deferred renderers only there is no crossover to find, and it says so.
grep -q "^bench: the quick sweep: 8 cases" "$out.stderr" && grep -q "^bench: results will be in $out/" "$out.stderr" ||
    { echo "FAIL: the run did not say what it would do: $(head -3 "$out.stderr")"; exit 1; }
"$bench" --quick --cutoffs none --pbr-scenes none --renderers deferred-volumes,deferred-stencil --out "$out/none" \
    >/dev/null 2>&1 || { echo "FAIL: --cutoffs none"; exit 1; }
if grep -q "^## Speed against error" "$out/none/bench.md" || [ -e "$out/none/speed_vs_error.png" ] ||
   grep -q "^## Metallic-roughness" "$out/none/bench.md" || grep -q "^pbr," "$out/none/bench.csv" ||
   ! grep -q "^None to find: --renderers holds only deferred" "$out/none/bench.md"; then
    echo "FAIL: --cutoffs none with deferred renderers only: $(grep -A2 '^## Crossover' "$out/none/bench.md")"; exit 1
fi
# Bad options: exit 2 with one line.
"$bench" --no-such-option >/dev/null 2>"$out.err"; rc=$?
if [ "$rc" -ne 2 ] || [ "$(wc -l <"$out.err")" -ne 1 ]; then
    echo "FAIL: a bad option gave exit $rc and $(wc -l <"$out.err") line(s) on stderr"; exit 1
fi
"$bench" --lights 1,x >/dev/null 2>&1; rc=$?
[ "$rc" -eq 2 ] || { echo "FAIL: --lights 1,x gave exit $rc"; exit 1; }
echo "ok: bench --quick output has the expected shape"
