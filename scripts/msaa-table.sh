#!/usr/bin/env bash
# msaa-table.sh BIN_DIR SIZE TITLE [ARGS...] - chapter 13's sweep for its page: deferred MSAA against
# forward MSAA (ARGS: the scene and lights, e.g. --lights 1024), at every sample count in 1 2 4 8 16
# the context allows (a count it refuses, or would round up, is left out). Per row: the median ms per frame of --bench
# (glFinish + monotonic clock, after warm-up frames), the edge pixels' fraction, and the MiB of each
# renderer's multisampled targets (deferred: the G-buffer; forward: RGBA16F colour + D32F depth).
# Prints a markdown section "## TITLE" on stdout; scripts/update-docs.sh puts it in the dated run.
set -euo pipefail
bin=$1 size=$2 title=$3
shift 3
chapter="$bin/13_msaa"
[ -x "$chapter" ] || { echo "msaa-table.sh: no $chapter (build first)" >&2; exit 2; }

# key=value from a line: field NAME LINE
field() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<" $2"; }

run() { # run SAMPLES RENDERER -> "median_ms mib edge_fraction", or nothing when refused
  local out bench msaa
  out=$("$chapter" --headless --size "$size" --frames 10 --bench --samples "$1" --renderer "$2" "${extra[@]}" \
    2>/dev/null) || return 0
  bench=$(grep '^bench:' <<<"$out") msaa=$(grep '^msaa:' <<<"$out")
  echo "$(field median_ms "$bench") $(field msaa_mib "$msaa") $(field edge_fraction "$msaa")"
}

extra=("$@")
echo "## $title"
echo ""
echo "Chapter 13 at $size${extra[*]:+, ${extra[*]}}: median ms per frame (\`--bench\`, 10 frames after"
echo "3 warm-up frames, glFinish + monotonic clock), the fraction of pixels shaded per sample (edges),"
echo "and the memory of the multisampled targets. Sample counts the context does not offer are left out."
echo ""
echo "| samples | deferred ms | forward ms | Forward+ ms | deferred / forward | edge pixels | G-buffer MiB | forward target MiB |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|"
for n in 1 2 4 8 16; do
  read -r d_ms d_mib edges <<<"$(run "$n" deferred)" || true
  read -r f_ms f_mib _ <<<"$(run "$n" forward)" || true
  read -r p_ms _ _ <<<"$(run "$n" forward-plus)" || true
  [ -n "${d_ms:-}" ] && [ -n "${f_ms:-}" ] && [ -n "${p_ms:-}" ] || continue
  awk -v n="$n" -v d="$d_ms" -v f="$f_ms" -v p="$p_ms" -v e="$edges" -v dm="$d_mib" -v fm="$f_mib" \
    'BEGIN { printf "| %d | %.1f | %.1f | %.1f | %.2f | %.2f %% | %.1f | %.1f |\n", n, d, f, p, d / f, 100 * e, dm, fm }'
done
echo ""
