#!/usr/bin/env bash
# shadow-table.sh BIN_DIR SIZE FRAMES [TARGET_SIZE] - chapter 14's benchmark for its page: the seed's experiment on
# the teapot scene (8 teapots and a floor, 80 point lights): deferred, Forward+ and forward with
# shadows, for 0, 8, 16, 32 and 80 shadowed lights (--shadows N) and 256 (the scene's 80 lights and
# copies of them turned about the vertical axis), lights still (every tile cached after the first
# frame) and moving (every light on a key path, --time-step 0.1: every tile drawn every frame),
# with the per-tile caster culling (and without it, deferred, at 80 and 256). Per row: the median ms per frame of --bench
# (FRAMES frames after 1 warm-up frame, glFinish + monotonic clock), the shadow pass's median, and
# from the last frame's `shadows:` line the tiles and triangles drawn; chapter 11 (no shadows) is
# the baseline, its frame less the pass that counts its light-loop iterations (count_ms, which --bench
# adds to chapter 11 and chapter 14 does not run). Then the issue's targets, met or missed, with the
# numbers (still lights against chapter 11 measured again at TARGET_SIZE, default 800x800, as the
# issue states them), and the still deferred frame by pass at each PCF. Prints markdown sections on
# stdout; scripts/update-docs.sh writes them to docs/data/shadow-bench.md.
set -euo pipefail
bin=$1 size=$2 frames=$3 target_size=${4:-800x800}
chapter="$bin/14_shadows" base="$bin/11_clustered"
for b in "$chapter" "$base"; do [ -x "$b" ] || { echo "shadow-table.sh: no $b (build first)" >&2; exit 2; }; done
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The scenes: the teapots' lights, COPIES times (turned by 360/COPIES degrees each time), the first
# N of them; moving: each light then goes 2 units along x in 100 s (a key path; 0.002 a frame).
make_scene() { # make_scene OUT LIGHTS COPIES MOVING
  awk -v models="$root/assets/models/" -v n="$2" -v copies="$3" -v moving="$4" '
    { sub(/file \.\.\/models\//, "file " models) }
    /^light / { for (i = 1; i <= NF; i++) if ($i == "position") k = i
                lines[++count] = $0; px[count] = $(k + 1); py[count] = $(k + 2); pz[count] = $(k + 3); at = k; next }
    { print }
    END {
      made = 0
      for (c = 0; c < copies && made < n; c++) {
        a = 2 * 3.14159265358979 * c / copies
        for (j = 1; j <= count && made < n; j++) {
          split(lines[j], f, " ")
          x = px[j] * cos(a) + pz[j] * sin(a); z = -px[j] * sin(a) + pz[j] * cos(a)
          f[at + 1] = sprintf("%.4f", x); f[at + 3] = sprintf("%.4f", z)
          line = f[1]; for (i = 2; i <= length(f); i++) line = line " " f[i]
          print line
          if (moving) printf "key 0 position %.4f %s %.4f\nkey 100 position %.4f %s %.4f\n", x, py[j], z, x + 2, py[j], z
          made++
        }
      }
    }' "$root/assets/scenes/teapots.scene" >"$1"
}
for moving in 0 1; do
  make_scene "$tmp/teapots80_$moving.scene" 80 1 "$moving"
  make_scene "$tmp/teapots256_$moving.scene" 256 4 "$moving"
done

field() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<" $2"; }

# One run: BINARY ARGS... -> "median_ms shadow_ms tiles_drawn triangles triangles_unculled dropped atlas_mib"
run() {
  local out bench sh
  out=$(nice -n 10 "$@" --headless --size "${run_size:-$size}" --frames "${run_frames:-$frames}" --warmup 1 --bench 2>/dev/null)
  bench=$(grep '^bench:' <<<"$out") sh=$(grep '^shadows:' <<<"$out" || true)
  # a frame's time without the count pass --bench adds to chapter 11 (count_ms; chapter 14 runs none)
  local count; count=$(field count_ms "$bench")
  echo "$(awk -v m="$(field median_ms "$bench")" -v c="${count:-0}" 'BEGIN { printf "%.3f", m - c }') $(field shadows_ms "$bench") $(field tiles_drawn "$sh") $(field triangles "$sh")" \
       "$(field triangles_unculled "$sh") $(field dropped "$sh") $(field atlas_mib "$sh")"
}

renderers=(deferred forward-plus forward)
declare -A base_ms
echo "## table"
echo ""
echo "Chapter 14 on the teapot scene at $size: median ms per frame (\`--bench\`, $frames frames after 1 warm-up"
echo "frame, glFinish + monotonic clock), the shadow pass's median (\`shadows\`), and the last frame's tiles and"
echo "shadow triangles drawn (with the culling, and what the same tiles would draw without it). Chapter 11's"
echo "frame (no shadows) is the baseline: ×11 is the frame time over its. Chapter 11's frame is timed without"
echo "the pass that counts its light-loop iterations for \`--bench\` (its \`count_ms\`, taken off its median):"
echo "chapter 14 runs no such pass."
echo ""
echo "| renderer | shadowed lights | lights | culling | ms still | ×11 | ms moving | ×11 | shadow pass ms (moving) | tiles drawn (moving) | shadow triangles (moving) | without culling | dropped |"
echo "|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for r in "${renderers[@]}"; do
  for lights in 80 256; do
    read -r ms _ <<<"$(run "$base" --renderer "$r" --scene "$tmp/teapots${lights}_0.scene")"
    base_ms[$r$lights]=$ms
  done
  for n in 0 8 16 32 80 256; do
    lights=80 shadows=(--shadows "$n")
    [ "$n" -eq 256 ] && lights=256 shadows=()
    culls=(on)
    [ "$r" = deferred ] && [ "$n" -ge 80 ] && culls=(on off)
    for cull in "${culls[@]}"; do
      args=(--renderer "$r" "${shadows[@]}" --shadow-cull "$cull")
      read -r still _ _ _ _ _ mib <<<"$(run "$chapter" "${args[@]}" --scene "$tmp/teapots${lights}_0.scene")"
      read -r moving shadow tiles tri unculled dropped _ <<<"$(run "$chapter" "${args[@]}" --time-step 0.1 \
        --scene "$tmp/teapots${lights}_1.scene")"
      echo "$r $n $lights $cull $still $moving $shadow $tiles $tri $unculled $dropped $mib ${base_ms[$r$lights]}" >>"$tmp/rows"
      awk -v r="$r" -v n="$n" -v l="$lights" -v c="$cull" -v s="$still" -v m="$moving" -v sh="$shadow" -v t="$tiles" \
        -v tri="$tri" -v u="$unculled" -v d="$dropped" -v b="${base_ms[$r$lights]}" \
        'BEGIN { printf "| %s | %d | %d | %s | %.0f | %.2f | %.0f | %.2f | %.0f | %d | %d | %d | %d |\n",
                 r, n, l, c, s, s / b, m, m / b, sh, t, tri, u, d }'
    done
  done
done
echo ""
echo "Chapter 11 (no shadows): $(for r in "${renderers[@]}"; do printf '%s %.0f ms (80 lights), %.0f ms (256); ' \
  "$r" "${base_ms[${r}80]}" "${base_ms[${r}256]}"; done | sed 's/; $//'). Atlas: $mib MiB (4096², d32f)."
echo ""
echo "## targets"
echo ""
target_frames=5 # the frame time the targets compare: 5 frames after the warm-up, not the table's FRAMES
for r in "${renderers[@]}"; do
  read -r still _ <<<"$(run_size=$target_size run_frames=$target_frames run "$chapter" --renderer "$r" --scene "$tmp/teapots80_0.scene")"
  read -r ms _ <<<"$(run_size=$target_size run_frames=$target_frames run "$base" --renderer "$r" --scene "$tmp/teapots80_0.scene")"
  echo "target $r $still $ms" >>"$tmp/rows"
done
awk -v size="$target_size" -v table="$size" '
  $1 == "deferred" && $2 == 80 && $4 == "on" { cull_on = $10 ? $9 / $10 : 0; on_ms = $6; tri = $9; unc = $10 }
  $1 == "deferred" && $2 == 80 && $4 == "off" { off_ms = $6 }
  $1 == "target" { ratio[$2] = $3 / $4; still[$2] = $3; base[$2] = $4 }
  END {
    saved = 100 * (1 - cull_on)
    printf "- culling: %.1f %% fewer shadow triangles with 80 moving lights (%d against %d; target ≥ 20 %%): %s;", saved, tri, unc, (saved >= 20 ? "**met**" : "**missed**")
    printf " the moving deferred frame at %s %.0f ms with it, %.0f ms without\n", table, on_ms, off_ms
    for (r in ratio)
      printf "- still lights, all 80 shadowed and cached, %s at %s: %.0f ms against %.0f ms unshadowed (chapter 11) = %.2f× (target ≤ 1.25×): %s\n", r, size, still[r], base[r], ratio[r], (ratio[r] <= 1.25 ? "**met**" : "**missed**")
  }' "$tmp/rows"
echo ""

# Where the still frame's time goes: the deferred frame's passes at TARGET_SIZE, chapter 11 against
# chapter 14 with each filter (the default first): the shadows add to the lighting pass alone.
echo "## still lights by pass"
echo ""
echo "The still deferred frame at $target_size, all 80 lights shadowed and cached: each pass's median ms over"
echo "$target_frames frames (\`--bench\`). Chapter 11 counts its light-loop iterations in a pass of its own"
echo "(count), which its frame above leaves out."
echo ""
echo "| frame | median ms | geometry | light assignment | lighting | count |"
echo "|---|---:|---:|---:|---:|---:|"
pass_row() { # LABEL BINARY ARGS...
  local out
  out=$(nice -n 10 "${@:2}" --headless --size "$target_size" --frames "$target_frames" --warmup 1 --bench \
        --scene "$tmp/teapots80_0.scene" 2>/dev/null | grep '^bench:')
  awk -v label="$1" -v m="$(field median_ms "$out")" -v g="$(field geometry_ms "$out")" \
      -v a="$(field light_assignment_ms "$out")" -v l="$(field lighting_ms "$out")" -v c="$(field count_ms "$out")" \
      'BEGIN { printf "| %s | %.0f | %.0f | %.0f | %.0f | %s |\n", label, m, g, a, l, (c == "" ? "—" : sprintf("%.0f", c)) }'
}
pass_row "chapter 11 (no shadows)" "$base"
for pcf in 1 3 5; do
  pass_row "chapter 14, --pcf $pcf$([ "$pcf" = 1 ] && echo ' (default)')" "$chapter" --pcf "$pcf"
done
echo ""
