#!/usr/bin/env bash
# forward-plus-table.sh BENCH_CSV - from one benchmark run's bench.csv, the section the issue of
# the many-light chapters asks the report for: per scene and light count, Forward+ (chapter 11's
# clustered forward) against the fastest deferred renderer of the same case, and which wins.
# scripts/update-docs.sh appends it to the run's bench.md; it reads nothing but the CSV.
set -euo pipefail
awk -F, '
NR == 1 { next }
$1 != "lights" || $16 == "skipped" { next }
{
    key = $2 SUBSEP $5 SUBSEP $4
    if (!(key in seen)) { seen[key] = 1; order[++n] = key }
    if ($3 == "forward-plus") { plus[key] = $12; plus_ratio[key] = $21 }
    else if ($3 ~ /^deferred-/ && (!(key in best) || $12 + 0 < best[key] + 0)) {
        best[key] = $12; best_name[key] = $3; best_ratio[key] = $21
    }
}
END {
    print "## Forward+ against the best deferred"
    print ""
    print "Per case: chapter 11'\''s Forward+ (`forward-plus`: depth pre-pass, then every object shaded once,"
    print "looping over its cluster'\''s lights) against the fastest deferred renderer of the same case,"
    print "median ms; cases too slow to run (extrapolated) are left out."
    print ""
    print "| scene | lights | forward-plus ms | best deferred | its ms | faster | forward-plus / best deferred |"
    print "|---|---|---:|---|---:|---|---:|"
    for (i = 1; i <= n; i++) {
        k = order[i]
        if (!(k in plus) || !(k in best)) continue
        split(k, p, SUBSEP)
        label = p[2] (p[3] == "scene" ? " (scene'\''s)" : "")
        faster = plus[k] + 0 < best[k] + 0 ? "Forward+" : best_name[k]
        printf "| %s | %s | %.1f | %s | %.1f | %s | %.2f |\n", p[1], label, plus[k], best_name[k], best[k], faster, plus[k] / best[k]
    }
}' "$1"
