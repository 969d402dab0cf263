#!/usr/bin/env bash
# run_bench_storage.sh BENCH OUT_DIR - run `bench --quick --storage only` (the storage table of
# docs/16_visibility_buffer.md on the default scene, 160x160) and check its shape and the one number
# the issue sets as a target: the visibility buffer stores at most 8 bytes per sample, depth included,
# at 1 and 4 samples; counted by common/gl/draw_count.c (the visibility pass's bytes written
# over its samples that passed, from the formats bound when it drew), never typed in. Every other row
# is measured or says why not. The timing-only rows (chapter 16's visibility pass cut down, --vis-pass
# no-primitive-id and depth-only) are timed, with no bytes and no error, and the section's last table
# puts their first pass beside the compact G-buffer's and the visibility buffer's: a time in each
# cell, none checked against another. Run alone, the part writes bench_storage.csv and
# bench_storage.md only: the main sweep's files seeded in OUT_DIR stay as they were, and its last line
# names those two files (tests/bench/partial_run.sh). Exit 77 (no GL context) passes through as a skip.
set -u
. "$(dirname "$0")/../lib/args.sh"
. "$(dirname "$0")/partial_run.sh"
args_expect 2 "$@"
bench=$1
out=$2
args_fresh_dir "$out"
partial_seed "$out"
"$bench" --quick --storage only --out "$out" >"$out.stdout" 2>"$out.stderr"
rc=$?
if [ "$rc" -eq 77 ]; then
    echo "skip: no GL context"
    exit 77
fi
if [ "$rc" -ne 0 ]; then
    echo "FAIL: bench --quick --storage only exited $rc"; cat "$out.stderr"; exit 1
fi
for f in bench_storage.csv bench_storage.md; do
    [ -s "$out/$f" ] || { echo "FAIL: $out/$f missing or empty"; exit 1; }
done
partial_check "$out" "$out.stdout" "$out.stderr" bench_storage.csv bench_storage.md || exit 1

# The CSV: its header; per (renderer, samples) one `total` row, after its passes when measured.
awk -F, '
NR == 1 {
    want = "scene,lights,renderer,samples,pass,width,height,frames,draws,samples_passed_per_px," \
           "written_bytes_per_px,read_bytes_per_px,scene_data_bytes_per_px,stored_bytes_per_sample,ms," \
           "max_abs_8bit,mean_abs_8bit,psnr_8bit,pixels_over_1,pass_clock,note"
    if ($0 != want) { print "FAIL: header is\n  " $0 "\nwanted\n  " want; bad = 1 }
    ncol = NF; next
}
{
    if (NF != ncol) { printf "FAIL: row %d has %d fields, header %d\n", NR, NF, ncol; bad = 1 }
    if ($1 != "default") { printf "FAIL: row %d: scene %s (--quick: the default scene)\n", NR, $1; bad = 1 }
    if ($3 ~ /^vis-/) {
        # timing only: times, every byte and error column NA, the note that says so
        key = $3 "/" $4
        if ($3 != "vis-no-primitive-id" && $3 != "vis-depth-only") { printf "FAIL: timing row %s\n", key; bad = 1 }
        if ($21 !~ /^timing only: /) { printf "FAIL: %s: note \"%s\"\n", key, $21; bad = 1 }
        for (i = 9; i <= 14; i++) if ($i != "NA") { printf "FAIL: %s: column %d is %s, not NA\n", key, i, $i; bad = 1 }
        for (i = 16; i <= 19; i++) if ($i != "NA") { printf "FAIL: %s: column %d is %s, not NA\n", key, i, $i; bad = 1 }
        if (!($15 > 0)) { printf "FAIL: %s %s: ms %s\n", key, $5, $15; bad = 1 }
        if ($5 == "visibility pass") timed_first[key] = 1
        if ($5 == "total") { timing_totals++; if (!timed_first[key]) { printf "FAIL: %s has no visibility pass\n", key; bad = 1 } }
        next
    }
    if ($5 != "total") { passes[$3 "/" $4]++; next }
    totals++
    key = $3 "/" $4
    if ($11 == "NA") {
        # not measured: a 4-sample row of a renderer without a variant, with the reason
        if ($4 != 4 || $21 !~ /^no 4-sample variant/) { printf "FAIL: %s not measured: \"%s\"\n", key, $21; bad = 1 }
        next
    }
    measured++
    if (passes[key] < 2) { printf "FAIL: %s has %d passes\n", key, passes[key]; bad = 1 }
    if (!($11 > 0 && $15 > 0 && $14 > 0)) { printf "FAIL: %s: bytes %s, ms %s, stored %s\n", key, $11, $15, $14; bad = 1 }
    if ($16 == "NA" || $16 > 255) { printf "FAIL: %s: 8-bit error %s\n", key, $16; bad = 1 }
    if ($3 == "visibility-buffer") {
        vis++
        if ($14 > 8) { printf "FAIL: the visibility buffer stores %s bytes per sample at %s sample(s): more than 8\n", $14, $4; bad = 1 }
        if ($13 <= 0) { printf "FAIL: the visibility buffer fetched no scene data\n"; bad = 1 }
    }
    if ($3 == "gbuffer-reference" && $4 == 1) ref = $14
    if ($3 == "gbuffer-compact" && $4 == 1) compact = $14
}
END {
    if (totals != 14) { printf "FAIL: %d total rows, want 7 renderers x 2 sample counts\n", totals; bad = 1 }
    # the light pre-pass has no 4-sample variant; every other renderer has both
    if (measured != 12) { printf "FAIL: %d rows measured, want 12\n", measured; bad = 1 }
    if (vis != 2) { printf "FAIL: %d visibility-buffer rows measured, want 2 (1 and 4 samples)\n", vis; bad = 1 }
    if (timing_totals != 4) { printf "FAIL: %d timing-only rows, want 2 x 2 sample counts\n", timing_totals; bad = 1 }
    # the layouts differ by their normal target only: RGBA16F against 2 x 12 bits in RGBA8
    if (ref - compact != 4) { printf "FAIL: reference G-buffer %s B/sample, compact %s: want 4 apart\n", ref, compact; bad = 1 }
    if (!bad) printf "ok: %d rows measured, the visibility buffer within 8 bytes per sample; %d timing-only rows\n", measured, timing_totals
    exit bad
}' "$out/bench_storage.csv" || exit 1

# The report: the section, its targets, one table row per (renderer, samples).
md="$out/bench_storage.md"
grep -q "^## What to store per pixel" "$md" || { echo "FAIL: bench_storage.md lacks the section"; exit 1; }
for n in 1 4; do
    grep -q "^- the visibility buffer stores at most 8 bytes per sample, depth included, at $n sample(s): measured [0-9.]*.*: met$" \
        "$md" || { echo "FAIL: the $n-sample target line: $(grep 'stores at most' "$md")"; exit 1; }
done
rows=$(awk '/^## What to store per pixel/ { s = 1 } s && /^### default/ { t = 1; next } /^#/ { t = 0 }
            t && /^\| [a-z]/ && !/^\| renderer/' "$md" | wc -l)
[ "$rows" -eq 14 ] || { echo "FAIL: the default scene's table has $rows rows, want 14"; exit 1; }
# ... and its last part: the first passes side by side, one row per sample count, a time in each cell.
times=$(awk '/^## / { s = ($0 == "## What to store per pixel") } s && /^### / { t = ($0 == "### What the visibility pass'"'"'s time is made of") }
             s && t' "$md")
grep -q '^| scene | samples | compact G-buffer: geometry | visibility pass | without gl_PrimitiveID | depth only |$' <<<"$times" ||
    { echo "FAIL: no table \"What the visibility pass's time is made of\" in the storage section"; exit 1; }
for n in 1 4; do
    grep -Eq "^\| default \| $n( \| [0-9]+\.[0-9]){4} \|$" <<<"$times" ||
        { echo "FAIL: the timing table's default x$n row: $(grep "^| default | $n " <<<"$times")"; exit 1; }
done
[ "$(grep -Ec '^\| [a-z]+ \| [0-9]' <<<"$times")" -eq 2 ] || { echo "FAIL: the timing table has other rows: $times"; exit 1; }
"$bench" --storage sometimes >/dev/null 2>&1; rc=$?
[ "$rc" -eq 2 ] || { echo "FAIL: --storage sometimes gave exit $rc"; exit 1; }
echo "ok: the storage table has its shape"
