#!/usr/bin/env bash
# run_bench_gbuffer.sh BENCH OUT_DIR - the benchmark's G-buffer sweep (tools/bench/bench_gbuffer.c)
# at --quick's size: bench_gbuffer.csv has one row per (scene, layout), its numbers are finite or
# NA, and what the layouts promise shows in them: the default is at most 12 bytes, the normal error
# follows the bits (2x8 > 2x12 > 2x16, each within tests/unit/test_octahedral.c's bound), reversed-Z
# rebuilds far positions more precisely than the standard float depth, and bench_gbuffer.md has the section.
# The third scene, pbr_teapots (metallic-roughness materials), is drawn by the layouts that can hold it
# (reference and oct16) only, oct16's normal the finer; every other layout has its row, untimed,
# saying it cannot hold them.
# Timings are never checked. Run alone, the part writes bench_gbuffer.csv and bench_gbuffer.md only:
# the main sweep's files seeded in OUT_DIR stay as they were (tests/bench/partial_run.sh).
set -u
. "$(dirname "$0")/../lib/args.sh"
. "$(dirname "$0")/../bench/partial_run.sh"
args_expect 2 "$@"
bench=$1
out=$2
args_fresh_dir "$out"
partial_seed "$out"
"$bench" --quick --gbuffer-sweep only --out "$out" >"$out.stdout" 2>"$out.stderr"
rc=$?
if [ "$rc" -eq 77 ]; then echo "skip: no GL context"; exit 77; fi
if [ "$rc" -ne 0 ]; then echo "FAIL: bench --gbuffer-sweep only exited $rc"; cat "$out.stderr"; exit 1; fi
partial_check "$out" "$out.stdout" "$out.stderr" bench_gbuffer.csv bench_gbuffer.md || exit 1
grep -q "^## G-buffer layouts" "$out/bench_gbuffer.md" ||
    { echo "FAIL: bench_gbuffer.md lacks '## G-buffer layouts'"; exit 1; }
awk -F, '
NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; ncol = NF; next }
{
    rows++
    if (NF != ncol) { printf "FAIL: row %d has %d fields, header %d\n", NR, NF, ncol; bad = 1 }
    for (i = col["frames"]; i < col["pass_clock"]; i++)
        if ($i != "NA" && $i !~ /^-?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?$/) {
            printf "FAIL: row %d column %d is \"%s\"\n", NR, i, $i; bad = 1
        }
    key = $col["scene"] "/" $col["layout"]
    normal[key] = $col["normal_max_deg"]; far[key] = $col["far_max_error"]
    if ($col["default"] == "yes") { defaults++; if ($col["bytes"] > 12) { print "FAIL: the default is " $col["bytes"] " bytes"; bad = 1 } }
    pbr = $col["scene"] == "pbr_teapots"
    if (pbr && $col["layout"] != "reference" && $col["layout"] != "oct16") {
        if ($col["median_ms"] != "NA" || $col["note"] !~ /cannot hold metallic-roughness/) {
            printf "FAIL: row %d: %s draws pbr_teapots or does not say it cannot (%s)\n", NR, $col["layout"], $col["note"]; bad = 1
        }
        next
    }
    if (pbr) pbr_measured++
    if ($col["median_ms"] == "NA" || $col["median_ms"] <= 0) { printf "FAIL: row %d has no time\n", NR; bad = 1 }
}
END {
    if (rows != 21) { printf "FAIL: %d rows, want 3 scenes x 7 layouts\n", rows; bad = 1 }
    if (defaults != 3) { printf "FAIL: %d default rows, want 3\n", defaults; bad = 1 }
    if (pbr_measured != 2) { printf "FAIL: %d layouts drew pbr_teapots, want 2 (reference, oct16)\n", pbr_measured; bad = 1 }
    p = "pbr_teapots/"
    if (!(normal[p "oct16"] < normal[p "reference"])) {
        print "FAIL: pbr_teapots: oct16 normal error " normal[p "oct16"] " not below reference " normal[p "reference"]; bad = 1
    }
    d = "default/"
    if (!(normal[d "oct8"] > normal[d "compact"] && normal[d "compact"] > normal[d "oct16"])) {
        print "FAIL: normal error does not follow the bits: " normal[d "oct8"] " " normal[d "compact"] " " normal[d "oct16"]; bad = 1
    }
    if (!(normal[d "oct8"] < 0.66 && normal[d "compact"] < 0.041 && normal[d "oct16"] < 0.0026 && normal[d "reference"] < 0.041)) {
        print "FAIL: a normal error over its unit-test bound"; bad = 1
    }
    split("default city", names, " ")
    for (k = 1; k <= 2; k++)
        if (!(far[names[k] "/reversed-z"] < far[names[k] "/compact"])) {
            print "FAIL: " names[k] ": reversed-z far error " far[names[k] "/reversed-z"] " not below compact " far[names[k] "/compact"]; bad = 1
        }
    if (!bad) printf "ok: %d rows\n", rows
    exit bad
}' "$out/bench_gbuffer.csv" || exit 1
"$bench" --gbuffer-sweep sometimes >/dev/null 2>"$out.err"; rc=$?
if [ "$rc" -ne 2 ] || [ "$(wc -l <"$out.err")" -ne 1 ]; then
  echo "FAIL: a bad --gbuffer-sweep gave exit $rc and $(wc -l <"$out.err") line(s)"; exit 1
fi
echo "ok: the G-buffer sweep's output has the expected shape"
