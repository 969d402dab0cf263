#!/usr/bin/env bash
# run_vis_pass.sh CHAPTER OUT_DIR - chapter 16's --vis-pass, which times what the visibility pass is
# made of (docs/16_visibility_buffer.md, "What it costs"): at 1 and 4 samples each mode runs, its
# --bench line still names the chapter's passes (the benchmark reads "visibility pass"), the two
# timing modes say once on stderr that their picture is not the chapter's (full says nothing),
# no-primitive-id shades the pixels full shades (the same depths, other triangles) and depth-only
# none (its ids stay the background); a bad mode exits 2 with one line that names it, and --help
# describes the option. Exit 77 (no GL context) passes through as a skip.
set -u
. "$(dirname "$0")/../lib/args.sh"
args_expect 2 "$@"
bin=$1 out=$2
args_fresh_dir "$out"
fail() { echo "FAIL: $*"; exit 1; }
for samples in 1 4; do
    passes="visibility_pass_ms=[0-9.]* light_assignment_ms=[0-9.]* shading_ms=[0-9.]*"
    [ "$samples" = 4 ] && passes="$passes shading_edges_ms=[0-9.]*"
    for mode in full no-primitive-id depth-only; do
        run=$out/$mode.x$samples
        "$bin" --headless --size 160x120 --frames 1 --warmup 0 --gl-debug --bench --samples "$samples" \
            --vis-pass "$mode" >"$run.out" 2>"$run.err"
        rc=$?
        [ $rc -eq 77 ] && { echo "skip: no GL context"; exit 77; }
        [ $rc -eq 0 ] || fail "--vis-pass $mode --samples $samples exited $rc: $(cat "$run.err")"
        grep -q " $passes " "$run.out" || fail "--vis-pass $mode x$samples: no '$passes' in: $(cat "$run.out")"
        warned=$(grep -c "^warning: 16_visibility_buffer: --vis-pass $mode: the picture is not the chapter's, timing only$" "$run.err")
        want=1
        [ "$mode" = full ] && want=0
        [ "$warned" -eq "$want" ] || fail "--vis-pass $mode x$samples warned $warned time(s), want $want: $(cat "$run.err")"
        shaded=$(grep -o ' shaded_pixels=[0-9]*' "$run.out" | cut -d= -f2)
        [ -n "$shaded" ] || fail "--vis-pass $mode x$samples: no shaded_pixels"
        case $mode in
          full) full=$shaded ;;
          no-primitive-id) [ "$shaded" -eq "$full" ] || fail "no-primitive-id x$samples shaded $shaded pixels, full $full" ;;
          depth-only) [ "$shaded" -eq 0 ] || fail "depth-only x$samples shaded $shaded pixels, want 0" ;;
        esac
        echo "ok: --vis-pass $mode x$samples: shaded_pixels=$shaded, warned $warned"
    done
done
"$bin" --headless --size 64x48 --frames 1 --vis-pass sometimes >"$out/bad.out" 2>"$out/bad.err"
rc=$?
[ $rc -eq 2 ] || fail "--vis-pass sometimes exited $rc, want 2"
[ "$(wc -l <"$out/bad.err")" -eq 1 ] && grep -q "unknown --vis-pass value 'sometimes' (one of: full no-primitive-id depth-only)" \
    "$out/bad.err" || fail "--vis-pass sometimes said: $(cat "$out/bad.err")"
"$bin" --help | grep -q -- "--vis-pass MODE .*the visibility pass" || fail "--help does not describe --vis-pass"
echo "ok: --vis-pass: every mode runs and names its passes, a bad one exits 2"
