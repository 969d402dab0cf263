#!/usr/bin/env bash
# run_refusals.sh BIN_DIR - what --gbuffer refuses, with exit 2 and one clear line on stderr:
# an unknown layout in every chapter, and reversed-z where the chapter's lighting pass tests the
# G-buffer's depth as standard depth (every chapter with a lighting pass state: 04 on); chapters 02
# and 03 take it, and 11, 17 and 19, whose one full-screen shading pass tests no depth.
set -u
bin=$1
pass=0 fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# expect CODE STDERR_SUBSTRING CHAPTER ARGS...
expect() {
  local code=$1 want=$2 chapter=$3
  shift 3
  "$bin/$chapter" --headless --size 64x48 --frames 1 "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$?
  if [ "$rc" -eq 77 ]; then echo "skip: no GL context"; exit 77; fi
  if [ "$rc" -ne "$code" ]; then
    fail=$((fail + 1)); echo "FAIL [$chapter $*]: exit $rc, expected $code: $(head -3 "$tmp/err")"
  elif [ -n "$want" ] && ! grep -qF -- "$want" "$tmp/err"; then
    fail=$((fail + 1)); echo "FAIL [$chapter $*]: stderr lacks '$want': $(head -3 "$tmp/err")"
  elif [ "$code" -eq 2 ] && [ "$(grep -c . "$tmp/err")" -ne 1 ]; then
    fail=$((fail + 1)); echo "FAIL [$chapter $*]: expected one line on stderr, got $(grep -c . "$tmp/err")"
  else
    pass=$((pass + 1)); echo "ok   [$chapter $*] -> $rc"
  fi
}

expect 2 "unknown G-buffer layout 'tiny' (one of: reference compact" 07_face_culling --gbuffer tiny
expect 2 "unknown G-buffer layout ''" 03_fullscreen_phong --gbuffer
for chapter in 04_light_volumes 05_attenuation_radius 06_additive_blending 07_face_culling 08_stencil_volumes \
               09_spot_lights 10_tiled_deferred 12_transparency 13_msaa 14_shadows 15_light_prepass \
               16_visibility_buffer; do
  [ -x "$bin/$chapter" ] || continue
  expect 2 "G-buffer layout reversed-z: this chapter's lighting pass reads the G-buffer's depth" \
    "$chapter" --gbuffer reversed-z
done
# 11, 17 and 19 shade in one full-screen pass that reads depth through gbuffer_read.glsl only
for chapter in 00_forward 02_mrt_gbuffer 03_fullscreen_phong 11_clustered 17_ssao 19_image_based_light; do
  expect 0 "" "$chapter" --gbuffer reversed-z --screenshot "$tmp/shot.png"
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
