#!/usr/bin/env bash
# feature-table.sh BIN_DIR SIZE FRAMES - what each feature of the course costs: the same frame with
# the feature off and on, for the renderers deferred, forward-plus and forward. Two tables:
# - off: chapters 14 (--shadows 0), 17 (--ssao off), 19 (--ibl off --ssao off) and 18 (on the
#   Blinn-Phong default scene and on the teapots) against chapter 11 on the same scene and renderer,
#   with the target that a feature switched off costs at most 3 % (≤ 1.03×);
# - on: chapter 14's shadows on every light (per shadowed light too), chapter 17's occlusion,
#   chapter 19's probes, and chapter 18's material maps, metallic-roughness over Blinn-Phong and
#   emissive, each against the same frame without it (the PBR teapots, and copies of them made here).
# Each run: --bench, FRAMES frames after 1 warm-up frame, glFinish + monotonic clock; its median less
# the pass that counts shaded pixels for --bench (count_ms, in the chapters and renderers that run one:
# chapter 11's, and others'; the feature does not pay for it). The runs are interleaved:
# ROUNDS rounds (environment, default 3), each running every case once in one fixed order, so a
# machine that slows down for a while slows every case alike; a case's time is the median over rounds.
# Each run checks its bench line's features= against what its scene must use (a scene copy whose
# edit did nothing fails, exit 1). Exit 77 when a chapter has no GL context. Markdown on stdout,
# progress on stderr.
set -euo pipefail
[ $# -eq 3 ] || { echo "usage: feature-table.sh BIN_DIR SIZE FRAMES (ROUNDS=N in the environment, default 3)" >&2; exit 2; }
bin=$1 size=$2 frames=$3 rounds=${ROUNDS:-3}
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "feature-table.sh: ROUNDS must be a positive whole number, got '$rounds'" >&2; exit 2; }
for c in 11_clustered 14_shadows 17_ssao 18_pbr_materials 19_image_based_light; do
  [ -x "$bin/$c" ] || { echo "feature-table.sh: no $bin/$c (build first)" >&2; exit 2; }
done
root=$(cd "$(dirname "$0")/.." && pwd)
scenes=$root/assets/scenes
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The scene copies, written here with their relative paths (meshes, maps) made absolute: pbr_teapots
# without its maps; that, in Blinn-Phong materials; that, with one material emissive.
edit_materials() { # edit_materials IN EDIT OUT: IN with each material line through the awk program EDIT
  awk -v dir="$(cd "$(dirname "$1")" && pwd)/" '
    { for (i = 2; i <= NF; i++) if (($(i - 1) == "file" || $(i - 1) ~ /_map$/) && $i !~ /^\//) $i = dir $i }
    $1 != "material" { print; next }
    '"$2" "$1" >"$3"
}
# every `*_map PATH` pair left out (here and below, $ in single quotes is awk's)
# shellcheck disable=SC2016
edit_materials "$scenes/pbr_teapots.scene" \
  '{ line = $1; for (i = 2; i <= NF; i++) if ($i ~ /_map$/) i++; else line = line " " $i; print line }' \
  "$tmp/pbr_no_maps.scene"
# a rough equivalence: albedo the base colour, specular 0.5, shininess 2/α² − 2 with α = roughness²
# (the usual Beckmann-Phong match), at least 1; metallic dropped. The costs do not hang on the values.
# shellcheck disable=SC2016
edit_materials "$tmp/pbr_no_maps.scene" \
  '$3 != "pbr" { print; next }
   { delete v; for (i = 4; i <= NF; i++) v[$i] = i
     a = $(v["roughness"] + 1) ^ 2; s = a > 0 ? 2 / (a * a) - 2 : 1
     printf "material %s albedo %s %s %s specular 0.5 shininess %.4g\n", $2, $(v["base"] + 1), $(v["base"] + 2),
            $(v["base"] + 3), (s < 1 ? 1 : s) }' \
  "$tmp/pbr_blinn_phong.scene"
# shellcheck disable=SC2016
edit_materials "$tmp/pbr_no_maps.scene" '$3 == "pbr" && !done { $0 = $0 " emissive 0.2 0.1 0.05"; done = 1 } { print }' \
  "$tmp/pbr_emissive.scene"

# The cases: NAME CHAPTER SCENE FEATURES ARGS... (FEATURES: the bench line's features= it must print).
BP=point,blinn-phong MR=point,metallic-roughness
cases=(
  "c11_teapots 11_clustered $scenes/teapots.scene $BP"
  "c11_probes 11_clustered $scenes/teapots_probes.scene $BP"
  "c11_default 11_clustered $scenes/default.scene $BP"
  "c14_off 14_shadows $scenes/teapots.scene $BP --shadows 0"
  "c14_on 14_shadows $scenes/teapots.scene $BP"
  "c17_off 17_ssao $scenes/teapots.scene $BP --ssao off"
  "c17_on 17_ssao $scenes/teapots.scene $BP --ssao on"
  "c19_off 19_image_based_light $scenes/teapots_probes.scene $BP --ibl off --ssao off"
  "c19_on 19_image_based_light $scenes/teapots_probes.scene $BP --ibl on --ssao off"
  "c18_default 18_pbr_materials $scenes/default.scene $BP"
  "c18_teapots 18_pbr_materials $scenes/teapots.scene $BP"
  "c18_maps 18_pbr_materials $scenes/pbr_teapots.scene $MR,maps"
  "c18_no_maps 18_pbr_materials $tmp/pbr_no_maps.scene $MR"
  "c18_blinn_phong 18_pbr_materials $tmp/pbr_blinn_phong.scene $BP"
  "c18_emissive 18_pbr_materials $tmp/pbr_emissive.scene $MR,emissive"
)
renderers=(deferred forward-plus forward)

field() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<" $2"; }

# One run: CASE RENDERER ROUND -> a line "NAME RENDERER ROUND MS SHADOWED" in $tmp/runs.
run() {
  local name chapter scene want args r=$2 round=$3 out rc bench features count shadowed
  read -r name chapter scene want args <<<"$1"
  read -ra args <<<"${args:-}"
  echo "feature-table.sh: round $round/$rounds: $chapter --renderer $r ${args[*]:+${args[*]} }$(basename "$scene")" >&2
  rc=0
  out=$(nice -n 10 "$bin/$chapter" --renderer "$r" "${args[@]}" --scene "$scene" --headless --size "$size" \
        --frames "$frames" --warmup 1 --bench 2>"$tmp/stderr") || rc=$?
  if [ "$rc" -eq 77 ]; then echo "feature-table.sh: $chapter has no GL context" >&2; exit 77; fi
  if [ "$rc" -ne 0 ]; then
    echo "feature-table.sh: $chapter --renderer $r ${args[*]} --scene $scene exited $rc:" >&2
    cat "$tmp/stderr" >&2; exit 1
  fi
  bench=$(grep '^bench:' <<<"$out" || true)
  features=$(field features "$bench")
  if [ "$features" != "$want" ]; then
    echo "feature-table.sh: $chapter on $(basename "$scene") ($r) printed features=${features:-nothing}, wanted $want" >&2
    exit 1
  fi
  [ -s "$tmp/gl_renderer" ] || field gl_renderer "$bench" | tr _ ' ' >"$tmp/gl_renderer"
  count=$(field count_ms "$bench") shadowed=$(field shadowed "$(grep '^shadows:' <<<"$out" || true)")
  echo "$name $r $round $(awk -v m="$(field median_ms "$bench")" -v c="${count:-0}" 'BEGIN { printf "%.3f", m - c }') ${shadowed:--}" \
    >>"$tmp/runs"
}

for round in $(seq "$rounds"); do
  for r in "${renderers[@]}"; do
    for c in "${cases[@]}"; do run "$c" "$r" "$round"; done
  done
done

# Each case's median over rounds: "NAME RENDERER MS SHADOWED" in $tmp/medians.
sort -k1,1 -k2,2 -k4,4g "$tmp/runs" | awk '
  function flush() { if (n) printf "%s %s %.3f %s\n", key1, key2, (n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2), sh }
  $1 " " $2 != key1 " " key2 { flush(); key1 = $1; key2 = $2; n = 0; sh = $5 }
  { v[++n] = $4 }
  END { flush() }' >"$tmp/medians"

cpu=$(sed -n 's/^model name[[:space:]]*: *//p' /proc/cpuinfo | head -1)
echo "# What each feature costs"
echo ""
echo "Measured $(date -u '+%Y-%m-%d %H:%M UTC') on ${cpu:-an unnamed CPU} ($(nproc) cores), $(cat "$tmp/gl_renderer"), at $size;"
plural() { [ "$1" = 1 ] && echo "$1 $2" || echo "$1 $2s"; }
echo "each run $(plural "$frames" frame) after 1 warm-up frame (\`--bench\`, glFinish + monotonic clock), its median less"
echo "the pass that counts shaded pixels for \`--bench\` (\`count_ms\`, where a chapter runs one);"
echo "$(plural "$rounds" round), each running every case once in one order, and each case's median over the rounds."
echo ""
awk -f /dev/stdin "$tmp/medians" <<'EOF'
{ ms[$1, $2] = $3; shadowed[$1, $2] = $4 }
END {
  split("deferred forward-plus forward", rs, " ")
  print "## What a feature costs when off"
  print ""
  print "Each chapter with its feature off against chapter 11 (no feature) on the same scene and renderer;"
  print "the target: at most 1.03× chapter 11's frame. The teapots (80 lights) for 14, 17 and 18,"
  print "teapots_probes for 19 (chapter 11 on it too), and chapter 18 also on the Blinn-Phong default scene."
  print ""
  print "| case | renderer | scene | ms | chapter 11 ms | ratio | ≤ 1.03× |"
  print "|---|---|---|---:|---:|---:|---|"
  n = split("c14_off c17_off c19_off c18_default c18_teapots", cs, " ")
  label["c14_off"] = "14 `--shadows 0`"; base["c14_off"] = "c11_teapots"; scene["c14_off"] = "teapots"
  label["c17_off"] = "17 `--ssao off`"; base["c17_off"] = "c11_teapots"; scene["c17_off"] = "teapots"
  label["c19_off"] = "19 `--ibl off --ssao off`"; base["c19_off"] = "c11_probes"; scene["c19_off"] = "teapots_probes"
  label["c18_default"] = "18"; base["c18_default"] = "c11_default"; scene["c18_default"] = "default"
  label["c18_teapots"] = "18"; base["c18_teapots"] = "c11_teapots"; scene["c18_teapots"] = "teapots"
  for (i = 1; i <= n; i++)
    for (j = 1; j <= 3; j++) {
      c = cs[i]; r = rs[j]; a = ms[c, r]; b = ms[base[c], r]; q = b > 0 ? a / b : 0
      printf "| %s | %s | %s | %.2f | %.2f | %.3f | %s |\n", label[c], r, scene[c], a, b, q, (b > 0 && q <= 1.03 ? "met" : "**missed**")
    }
  print ""
  print "## What a feature costs when on"
  print ""
  print "Each feature on against the same frame with it off. Shadows: chapter 14 with every light shadowed"
  print "against `--shadows 0` on the teapots (the lights still: the atlas is drawn in the warm-up frame and"
  print "its tiles cached, so the timed frames pay the lookups), and that difference per shadowed light."
  print "SSAO: chapter 17 `--ssao on` against `off` (teapots). Image-based light: chapter 19 `--ibl on`"
  print "against `off`, both `--ssao off` (teapots_probes). The rest is chapter 18 on pbr_teapots and copies"
  print "of it: the material maps (pbr_teapots against the copy without its `*_map` attributes);"
  print "metallic-roughness over Blinn-Phong (the map-less copy against one whose materials are Blinn-Phong"
  print "with the same base colour, specular 0.5 and a shininess matched to the roughness: a rough"
  print "equivalence, the two models do not draw the same picture); emissive (the map-less copy with"
  print "`emissive 0.2 0.1 0.05` on one material, the floor's, against without)."
  print ""
  print "| feature | renderer | off ms | on ms | ratio | difference ms | per shadowed light ms |"
  print "|---|---|---:|---:|---:|---:|---:|"
  n = split("shadows:c14_off:c14_on ssao:c17_off:c17_on ibl:c19_off:c19_on maps:c18_no_maps:c18_maps" \
            " mr:c18_blinn_phong:c18_no_maps emissive:c18_no_maps:c18_emissive", fs, " ")
  name["shadows"] = "shadows"; name["ssao"] = "SSAO"; name["ibl"] = "image-based light"; name["maps"] = "material maps"
  name["mr"] = "metallic-roughness over Blinn-Phong"; name["emissive"] = "emissive"
  for (j = 1; j <= 3; j++)
    for (i = 1; i <= n; i++) {
      split(fs[i], f, ":"); r = rs[j]; off = ms[f[2], r]; on = ms[f[3], r]
      per = "—"
      if (f[1] == "shadows") {
        k = shadowed[f[3], r]
        per = k > 0 ? sprintf("%.3f (%d lights)", (on - off) / k, k) : "no light shadowed"
      }
      printf "| %s | %s | %.2f | %.2f | %.3f | %.2f | %s |\n", name[f[1]], r, off, on, (off > 0 ? on / off : 0), on - off, per
    }
  print ""
}
EOF
