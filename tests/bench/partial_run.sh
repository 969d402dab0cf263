# partial_run.sh - sourced by the scripts that run one part of the benchmark alone (--storage only,
# --ambient-sweep only, --gbuffer-sweep only): such a run must leave the main sweep's files in its
# folder as they were, announce the part it runs (not "the course sweep: 20 cases ..."), and name
# in its last line the files it wrote, no others.
#   partial_seed DIR
#       puts a sweep's files (marked as another run's) into DIR: bench.md, bench.csv, the plots
#   partial_check DIR STDOUT STDERR FILE...
#       fails (exit 1, with the reason) when a seeded file changed, when STDERR announces a sweep,
#       or when STDOUT's "bench: wrote into DIR/: ..." line does not list exactly the FILEs, in order

partial_files=(bench.md bench.csv bench_plots.gp time_vs_lights.png speed_vs_error.png)

partial_seed() {
    local f
    for f in "${partial_files[@]}"; do
        echo "another run's $f" >"$1/$f"
    done
}

partial_check() {
    local dir=$1 stdout=$2 stderr=$3 f want got
    shift 3
    for f in "${partial_files[@]}"; do
        [ "$(cat "$dir/$f" 2>/dev/null)" = "another run's $f" ] ||
            { echo "FAIL: the part run replaced or removed $dir/$f, another run's result"; return 1; }
    done
    if grep -E "the (course|full|quick) sweep|cases \(" "$stderr"; then
        echo "FAIL: a part run alone announces a sweep it does not run (above)"; return 1
    fi
    grep -q "^bench: no sweep, only the part" "$stderr" ||
        { echo "FAIL: no announcement of the part run:"; cat "$stderr"; return 1; }
    want="bench: wrote into $dir/: $(printf '%s\n' "$@" | sed '$!s/$/,/' | paste -sd' ' | sed 's/, \([^ ]*\)$/ and \1/')"
    got=$(grep "^bench: wrote" "$stdout")
    [ "$got" = "$want" ] || { echo "FAIL: the last line says"; echo "  $got"; echo "wanted"; echo "  $want"; return 1; }
    if grep -n -- "+-" "$stdout" "$stderr"; then
        echo "FAIL: a signed number printed with two signs (above)"; return 1
    fi
    return 0
}
