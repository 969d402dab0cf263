#!/usr/bin/env bash
# update-docs.sh [--quick] - one dated run behind every figure the pages show.
#
# Builds, then measures on this machine and writes docs/data/ (on a GPU: docs/data/gpu/, a second
# set the pages can show beside the software one):
#   chapters.md     every chapter's --bench line on the default scene (its 8 lights, and 256
#                   generated ones), deferred and forward, with each pass's median; and the
#                   tables of single chapters the pages discuss (02's views, 03's light counts,
#                   06's accumulation formats, 07's culling modes and the city, the
#                   hard-cases page's 200 overlapping lights at six cut-offs, the many-light
#                   chapters on their scenes, 11's two light assignments, 12's glass and 13's
#                   sample counts, scripts/msaa-table.sh; the "What it costs" tables of chapters 15, 16
#                   and 17: each option in a section, then the chapters they are measured against)
#   shadow-bench.md chapter 14 on the teapots: deferred, Forward+ and forward with 0 to 256 shadowed
#                   lights, still and moving, with and without the caster culling, against chapter 11
#                   (scripts/shadow-table.sh), and the issue's targets met or missed
#   shadows.md      chapter 14 against exact shadow rays (the hard.shadow_reference_* tests' tables)
#                   and the teapots' shadow pass with and without the culling (scripts/shadow-error.sh)
#   features.md     what each feature costs, off against chapter 11 and on against the same frame
#                   without it (scripts/feature-table.sh at 800x800: about a quarter of an hour)
#   storage/        build/bin/bench --storage only at 320x240: what to store per pixel (docs/16):
#                   bench_storage.md and .csv (a part run alone writes no bench.md);
#                   that part alone (about 7 minutes): scripts/update-docs.sh --storage-only
#   bench/          build/bin/bench's full sweep: bench.md, bench.csv, the two plots; its ambient
#                   sweep (chapters 17 and 19 against chapter 11's lighting pass, then their errors
#                   against the exact references): bench_ambient.md and its CSV files. By hand, that
#                   part alone (about 7 minutes): scripts/update-docs.sh --ambient-only
# Each file starts with the same stamp (date, CPU, cores, GL renderer, commit, clock). The pages
# embed sections of these files verbatim between <!-- generated: FILE#SECTION --> markers, and
# tests/lessons/doc_generated.py fails when a page's copy differs from the file (--update refreshes them).
# Takes about 50 minutes on 2 cores with llvmpipe (51 for the run of 2026-12-02 18:29, before features.md
# was part of it: count a quarter of an hour more); --quick (a few minutes) is for trying the script.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
quick=false ambient_only=false storage_only=false
[ "${1:-}" = "--quick" ] && quick=true
[ "${1:-}" = "--ambient-only" ] && ambient_only=true
[ "${1:-}" = "--storage-only" ] && storage_only=true
"$root/scripts/build.sh" "$root/build" >/dev/null
renderer=$(build/bin/00_forward --headless --gl-info | sed -n 's/^gl: renderer=//p')
# llvmpipe's run is the pages' main set; a GPU's goes beside it, so both can be shown side by side.
case $renderer in
  *llvmpipe*) data=docs/data ;;
  *) data=docs/data/gpu ;;
esac
mkdir -p "$data/bench"
version=$(build/bin/00_forward --headless --gl-info | sed -n 's/^gl: version=//p')
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
stamp="Measured $(date -u '+%Y-%m-%d %H:%M UTC') on ${cpu:-an unknown CPU} ($(nproc) cores), $renderer, \
$version; commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)$(git diff --quiet 2>/dev/null || echo '+changes'); \
frame times with glFinish and a monotonic clock; medians over the frames each table states."

# The ambient sweep's report with the stamp on top: DIR (where the benchmark wrote it) into $data/bench.
stamp_ambient() {
  { printf '%s\n\n' "$stamp"; cat "$1/bench_ambient.md"; } >"$data/bench/bench_ambient.md.tmp"
  [ "$1" = "$data/bench" ] || cp "$1"/bench_ambient*.csv "$data/bench/"
  mv "$data/bench/bench_ambient.md.tmp" "$data/bench/bench_ambient.md"
}
# What to store per pixel (docs/16_visibility_buffer.md): the storage table on its own, at 320x240 and
# 3 frames (about 7 minutes on 2 cores; the sweep's 800x800 has 8 times the pixels, and the bunnies'
# 7.3 M triangles at 4 samples already take seconds a frame here).
storage_table() {
  local storage_args=(--size 320x240 --frames 3 --warmup 1)
  $quick && storage_args=(--quick)
  build/bin/bench --storage only --out "$data/storage" --no-plots "${storage_args[@]}"
  { printf '%s\n\n' "$stamp"; cat "$data/storage/bench_storage.md"; } >"$data/storage/bench_storage.md.tmp"
  mv "$data/storage/bench_storage.md.tmp" "$data/storage/bench_storage.md"
  echo "wrote $data/storage/bench_storage.md"
}
if $storage_only; then
  storage_table
  /usr/bin/python3 tests/lessons/doc_generated.py --update "$root"
  echo "the pages now show it; review with: git diff docs"
  exit 0
fi
if $ambient_only; then # the benchmark's --full settings for that part only, beside the other files
  tmp=$(mktemp -d)
  build/bin/bench --full --ambient-sweep only --no-plots --out "$tmp"
  stamp_ambient "$tmp"
  rm -rf "$tmp"
  /usr/bin/python3 tests/lessons/doc_generated.py --update "$root"
  echo "wrote $data/bench/bench_ambient.md; the pages now show it; review with: git diff docs"
  exit 0
fi

# One table row from a --bench line: chapter, renderer (then LABEL, when given), median, passes,
# shaded pixels.
row() { # [LABEL]
  awk -v label="${1:-}" '/^bench:/ {
    for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2]
      if (kv[1] ~ /_ms$/ && kv[1] !~ /^(median|min|max|mean)_ms$/) {
        name = substr(kv[1], 1, length(kv[1]) - 3); gsub("_", " ", name)
        passes = passes (passes ? ", " : "") name " " kv[2] } }
    shaded = v["shaded_pixels"] == "-1" ? "—" : v["shaded_pixels"]   # the chapter does not count them
    printf "| %s | %s%s | %s | %s | %s |\n", v["chapter"], v["renderer"], label, v["median_ms"], passes, shaded
  }'
}

header() { # TITLE
  printf '## %s\n\n| chapter | renderer | median ms | passes (median ms) | shaded pixels |\n|---|---|---:|---|---:|\n' "$1"
}

# One --bench run as a table row: BINARY ARGS... (the default scene by name unless ARGS give one:
# chapters 09 and 12 open on their lesson's scene). A --vis-pass MODE in ARGS, which the bench line
# does not name, follows the renderer ("deferred --vis-pass depth-only"): one section runs chapter 16
# with each mode.
run() {
  local scene=(--scene assets/scenes/default.scene) args=" ${*:2} " label=""
  case $args in *" --scene "*) scene=() ;; esac
  if [[ $args == *" --vis-pass "* ]]; then
    label=${args#* --vis-pass }
    label=" --vis-pass ${label%% *}"
  fi
  "build/bin/$1" --headless --bench --frames 10 "${scene[@]}" "${@:2}" | row "$label"
}

# chapter_table TITLE ARGS...: every chapter, deferred then forward (chapter 00: its four renderers).
chapter_table() {
  local title=$1
  shift
  header "$title"
  for bin in build/bin/[0-9][0-9]_*; do
    local renderers=(deferred forward)
    case $(basename "$bin") in
      00_*) renderers=(forward forward-naive forward-prepass forward-lists) ;;
      01_*) renderers=(offscreen forward) ;;
      11_*) renderers=(deferred forward-plus forward) ;;
    esac
    for r in "${renderers[@]}"; do
      run "$(basename "$bin")" --renderer "$r" "$@"
    done
  done
  echo
}

# The tables of chapters 15 to 17's "What it costs": each option of the chapter in a section of its
# own, then the chapters it is measured against, at 800x800 (the heavy runs 5 frames, said in the
# section's name); chapter 15 on the PBR teapots at 320x240.
later_chapters() {
  local lights
  for lights in 8 1024; do
    local args=()
    [ "$lights" = 1024 ] && args=(--lights 1024)
    for specular in rgb mono; do
      header "15-$specular-$lights-lights-800x800"
      run 15_light_prepass --size 800x800 --specular "$specular" "${args[@]}"
      echo
    done
    header "15-against-$lights-lights-800x800"
    run 11_clustered --size 800x800 "${args[@]}"
    run 00_forward --size 800x800 "${args[@]}"
    echo
  done
  header "15-pbr-teapots-320x240-5-frames"
  for bin in 15_light_prepass 18_pbr_materials 00_forward; do
    run "$bin" --size 320x240 --frames 5 --scene assets/scenes/pbr_teapots.scene
  done
  echo
  header "16-default-800x800"
  run 16_visibility_buffer --size 800x800
  run 11_clustered --size 800x800
  echo
  header "16-bunnies-800x800-5-frames"
  run 16_visibility_buffer --size 800x800 --frames 5 --scene assets/scenes/bunnies.scene
  # what the visibility pass's time is made of: timing only, wrong pictures (docs/16, "What it costs")
  local vis_pass
  for vis_pass in no-primitive-id depth-only; do
    run 16_visibility_buffer --size 800x800 --frames 5 --scene assets/scenes/bunnies.scene --vis-pass "$vis_pass"
  done
  run 11_clustered --size 800x800 --frames 5 --scene assets/scenes/bunnies.scene
  echo
  local scene
  for scene in default teapots; do
    local frames=10
    [ "$scene" = teapots ] && frames=5
    local at=(--size 800x800 --frames "$frames" --scene "assets/scenes/$scene.scene")
    local name="800x800"
    [ "$frames" = 5 ] && name="800x800-5-frames"
    header "17-$scene-$name"
    run 17_ssao "${at[@]}"
    run 17_ssao "${at[@]}" --renderer forward
    echo
    header "17-ssao-off-$scene-$name"; run 17_ssao "${at[@]}" --ssao off; echo
  done
  header "17-ao-samples-4-default-800x800"; run 17_ssao --size 800x800 --ao-samples 4; echo
  header "17-ao-samples-64-default-800x800-5-frames"; run 17_ssao --size 800x800 --frames 5 --ao-samples 64; echo
}

# The pages' other tables: one option of one chapter at a time (the row says which in its renderer
# column only when the option is the renderer, so each table's title names what varies).
{
  printf '# Chapter timings\n\nEach row: `--bench --frames 10` (3 warm-up frames), the default scene unless the section says otherwise.\n\n%s\n\n' "$stamp"
  chapter_table "default-800x600" --size 800x600
  chapter_table "default-256-lights-800x600" --size 800x600 --lights 256
  for view in albedo final; do
    header "02-view-$view-800x600"; run 02_mrt_gbuffer --size 800x600 --view "$view"; echo
  done
  for n in 64 256; do
    header "03-$n-lights-800x600"
    run 03_fullscreen_phong --size 800x600 --lights "$n"
    run 03_fullscreen_phong --size 800x600 --lights "$n" --renderer forward
    echo
  done
  for accum in rgba16f rgba32f rgba8; do
    header "06-accum-$accum-800x600"; run 06_additive_blending --size 800x600 --accum "$accum"; echo
  done
  for cull in front back none; do
    header "07-cull-$cull-cutoff-0.1-800x600"; run 07_face_culling --size 800x600 --cutoff 0.1 --cull "$cull"; echo
  done
  for cutoff in 0 0.001953125 0.00390625 0.009765625 0.01953125 0.0390625; do # 0 .. 10/256
    header "hard-overlap-cutoff-$cutoff-320x240"
    run 07_face_culling --size 320x240 --scene tests/scenes/hard_overlap200.scene --cutoff "$cutoff"
    run 07_face_culling --size 320x240 --scene tests/scenes/hard_overlap200.scene --cutoff "$cutoff" \
      --renderer forward
    echo
  done
  header "07-city-800x800"
  run 07_face_culling --size 800x800 --scene assets/scenes/city.scene
  run 07_face_culling --size 800x800 --scene assets/scenes/city.scene --renderer forward
  echo
  # The many-light chapters on the scenes their pages discuss, one renderer per row.
  many_light() { # TITLE ARGS...: 07 and every later deferred chapter, then forward and Forward+
    header "$1"
    for bin in 07_face_culling 08_stencil_volumes 09_spot_lights 10_tiled_deferred 11_clustered; do
      [ -x "build/bin/$bin" ] && run "$bin" "${@:2}"
    done
    [ -x build/bin/11_clustered ] && run 11_clustered --renderer forward-plus "${@:2}"
    run 00_forward "${@:2}"
    echo
  }
  many_light "many-lights-city-800x800" --size 800x800 --scene assets/scenes/city.scene
  many_light "many-lights-default-1024-800x800" --size 800x800 --lights 1024
  many_light "many-lights-city-1024-800x800" --size 800x800 --scene assets/scenes/city.scene --lights 1024
  for volume in cone sphere; do
    header "09-spots-$volume-800x600"
    run 09_spot_lights --size 800x600 --scene assets/scenes/spots.scene --spot-volume "$volume"
    echo
  done
  header "09-spots-forward-800x600"; run 00_forward --size 800x600 --scene assets/scenes/spots.scene; echo
  for view in lit opaque; do
    header "12-glass-$view-800x600"
    run 12_transparency --size 800x600 --scene assets/scenes/glass.scene --view "$view"
    echo
  done
  header "12-glass-forward-800x600"; run 00_forward --size 800x600 --scene assets/scenes/glass.scene; echo
  header "12-glass-forward-plus-800x600"
  run 00_forward --size 800x600 --scene assets/scenes/glass.scene --renderer forward-plus
  echo
  # Chapter 11's light lists made on the CPU and by compute shaders: the same lists, other costs.
  for assign in cpu compute; do
    for scene in "default-1024|--lights 1024" "city|--scene assets/scenes/city.scene"; do
      read -r -a args <<<"${scene#*|}"
      header "11-assign-$assign-${scene%%|*}-800x800"
      for r in deferred forward-plus; do
        run 11_clustered --size 800x800 --assign "$assign" --renderer "$r" "${args[@]}"
      done
      echo
    done
  done
  scripts/msaa-table.sh build/bin 800x800 13-msaa-default-800x800
  scripts/msaa-table.sh build/bin 800x800 13-msaa-default-1024-800x800 --lights 1024
  scripts/msaa-table.sh build/bin 800x800 13-msaa-city-800x800 --scene assets/scenes/city.scene
  later_chapters
} >"$data/chapters.md.tmp"
mv "$data/chapters.md.tmp" "$data/chapters.md"
echo "wrote $data/chapters.md"

# Chapter 14's shadows on the teapots (scripts/shadow-table.sh: about 5 minutes on 2 cores; its targets at 800x800),
# a file of its own that docs/14_shadows.md embeds.
shadow_size=320x240 shadow_target=800x800
$quick && shadow_size=160x120 shadow_target=160x120
{
  printf '# Chapter 14: shadows on the teapots, timed\n\n%s\n\n' "$stamp"
  scripts/shadow-table.sh build/bin "$shadow_size" 2 "$shadow_target"
} >"$data/shadow-bench.md.tmp"
mv "$data/shadow-bench.md.tmp" "$data/shadow-bench.md"
echo "wrote $data/shadow-bench.md"
# ... and against exact shadow rays (scripts/shadow-error.sh: the hard.shadow_reference_* tests' tables,
# about 2 minutes), with the shadow pass's work on the teapots.
{
  printf "# Chapter 14: shadows against exact shadow rays, and the shadow pass's work\n\n%s\n\n" "$stamp"
  scripts/shadow-error.sh build
} >"$data/shadows.md.tmp"
mv "$data/shadows.md.tmp" "$data/shadows.md"
echo "wrote $data/shadows.md"

# What each feature costs (scripts/feature-table.sh), for docs/compare.md's "What each feature costs".
feature_size=800x800 feature_frames=5
$quick && feature_size=96x96 feature_frames=1
{
  printf '# What each feature costs\n\n%s\n\n' "$stamp"
  scripts/feature-table.sh build/bin "$feature_size" "$feature_frames"
} >"$data/features.md.tmp"
mv "$data/features.md.tmp" "$data/features.md"
echo "wrote $data/features.md"

storage_table

bench_args=(--full --storage off)
$quick && bench_args=(--quick --storage off)
build/bin/bench --out "$data/bench" "${bench_args[@]}"
# The stamp goes on top of the benchmark's own report, which names the machine too; Forward+ against
# the best deferred renderer, case by case, is read from the same run's CSV.
{ printf '%s\n\n' "$stamp"; cat "$data/bench/bench.md"; echo; scripts/forward-plus-table.sh "$data/bench/bench.csv"; } \
  >"$data/bench/bench.md.tmp"
mv "$data/bench/bench.md.tmp" "$data/bench/bench.md"
stamp_ambient "$data/bench"
/usr/bin/python3 tests/lessons/doc_generated.py --update "$root"
echo "the pages now show this run; review with: git diff docs"
