# work_lib.sh - sourced by the run_*_work.sh checks (chapters 08, 10, 11): the benchmark run and the
# chapter's own count that each of them compares, written once.
#   work_bench BENCH DIR SCENES LIGHTS RENDERERS
#       the benchmark at 800x800, one frame per point, no plots, into DIR (DIR/bench.csv); exits the
#       calling script with 77 (no GL context: a skip) or 1 (the benchmark failed)
#   work_csv DIR SCENE RENDERER LIGHTS COLUMN
#       one field of DIR/bench.csv's light sweep (columns: 1 sweep, 2 scene, 3 renderer,
#       4 light_set, 5 lights, 17 shaded, 19 ideal, 20 light_evals, 21 ratio, 24 max_abs_8bit,
#       25 mean_abs_8bit)
#   work_count CHAPTER ARGS...
#       the chapter's shaded_pixels (--bench) at 800x800 with 1024 generated lights, one frame

work_bench() {
    local bench=$1 dir=$2 extra=()
    mkdir -p "$dir"
    # the G-buffer layouts' sweep measures something else, and takes long
    "$bench" --help 2>&1 | grep -q -- '--gbuffer-sweep' && extra=(--gbuffer-sweep off)
    # nor the metallic-roughness rows
    "$bench" --help 2>&1 | grep -q -- '--pbr-scenes' && extra+=(--pbr-scenes none)
    # --max-frame-ms 1e9: every case runs; the skip predictor times frames, which a busy machine slows
    "$bench" --scenes "$3" --lights "$4" --renderers "$5" --size 800x800 --frames 1 --warmup 0 --cutoffs 5 \
        --cutoff-lights 64 --error-max-lights 0 --max-frame-ms 1e9 --no-plots "${extra[@]}" --out "$dir" \
        >"$dir/stdout" 2>"$dir/stderr"
    local rc=$?
    [ $rc -eq 77 ] && { echo "skip: no GL context"; exit 77; }
    [ $rc -ne 0 ] && { echo "FAIL: bench exited $rc"; cat "$dir/stderr"; exit 1; }
    return 0
}

work_csv() {
    awk -F, -v s="$2" -v r="$3" -v n="$4" -v c="$5" \
        '$1 == "lights" && $2 == s && $3 == r && $5 == n { print $c }' "$1/bench.csv"
}

work_count() {
    local chapter=$1
    shift
    "$chapter" --headless --size 800x800 --lights 1024 --frames 1 --warmup 0 --bench "$@" |
        sed -n 's/.*shaded_pixels=\([0-9-]*\).*/\1/p'
}
