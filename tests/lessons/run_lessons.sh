#!/usr/bin/env bash
# run_lessons.sh ROOT - each lesson's GL call appears first in the chapter that teaches it, so a
# reader who greps the chapters in order lands on the stage that introduces it.
set -u
root=$1
status=0
expect_first() { # STRING CHAPTER
  local first
  first=$(grep -lF -- "$1" "$root"/chapters/[0-9][0-9]_*.c | sort | head -n 1)
  if [ "$(basename "${first:-none}")" = "$2" ]; then
    echo "ok   '$1' first in $2"
  else
    echo "FAIL '$1' first in ${first:-no chapter}, expected $2"
    status=1
  fi
}
expect_first "glDrawElementsInstanced" 04_light_volumes.c
expect_first "FIXED_RADIUS" 04_light_volumes.c
expect_first "light_volumes_sort" 05_attenuation_radius.c
expect_first "GL_ONE, GL_ONE" 06_additive_blending.c
expect_first "GL_RGBA16F" 06_additive_blending.c
expect_first "GL_GREATER" 07_face_culling.c
expect_first "GL_DEPTH_CLAMP" 07_face_culling.c
expect_first "glStencilOpSeparate" 08_stencil_volumes.c
expect_first "GL_INCR_WRAP" 08_stencil_volumes.c
expect_first "GL_DECR_WRAP" 08_stencil_volumes.c
expect_first "GL_NOTEQUAL" 08_stencil_volumes.c
expect_first "stencil_only" 08_stencil_volumes.c
expect_first "gbuffer_create_with" 08_stencil_volumes.c
expect_first "light_batches_make" 08_stencil_volumes.c
expect_first "CONE_VOLUME" 09_spot_lights.c
expect_first "light_volumes_cone_create" 09_spot_lights.c
expect_first "gpu_light_is_spot" 09_spot_lights.c
expect_first "glDispatchCompute" 10_tiled_deferred.c
expect_first "glMemoryBarrier" 10_tiled_deferred.c
expect_first "glBindBufferBase(GL_SHADER_STORAGE_BUFFER" 10_tiled_deferred.c
expect_first "tiled_cull.comp" 10_tiled_deferred.c
expect_first "tile_depth_bounds.frag" 10_tiled_deferred.c
expect_first "tiled_shade.frag" 10_tiled_deferred.c
expect_first "tile_sphere_visible" 10_tiled_deferred.c
expect_first "chapter_11_assign" 11_clustered.c
expect_first "CLUSTER_ASSIGN_FILL" 11_clustered.c
expect_first "chapter_11_shade_deferred" 11_clustered.c
expect_first "chapter_11_shade_forward" 11_clustered.c
expect_first "GL_EQUAL" 00_forward.c
expect_first "forward_draw_depth" 00_forward.c
expect_first "GL_ONE_MINUS_SRC_ALPHA" 12_transparency.c
expect_first "clusters_shade_glass" 12_transparency.c
expect_first "CLUSTERS_VIEW_LINEAR" 11_clustered.c # the benchmark asks 11 for linear radiance (app.h: linear_output)
expect_first "GPU_SCENE_BACK_TO_FRONT" 12_transparency.c
expect_first "glCheckFramebufferStatus" 01_fbo_setup.c
expect_first "glDrawBuffers" 02_mrt_gbuffer.c
expect_first "light_prepass_thin.frag" 15_light_prepass.c
expect_first "light_prepass_accum.frag" 15_light_prepass.c
expect_first "light_prepass_combine.frag" 15_light_prepass.c
expect_first '"visibility.frag"' 16_visibility_buffer.c # the quote: not 14's shadow_visibility.frag
expect_first "visibility_shade.frag" 16_visibility_buffer.c
expect_first "glClearBufferuiv" 16_visibility_buffer.c
expect_first "ssao.frag" 17_ssao.c
expect_first "ssao_blur.frag" 17_ssao.c
expect_first "AMBIENT_OCCLUSION" 17_ssao.c
# No lesson behind a flag in common/: the old option structs are gone.
if grep -rn --include='*.[ch]' "light_volumes_options\|overwrite\b" "$root"/common; then
  echo "FAIL a chapter's lesson is selected by an option in common/"
  status=1
fi
# An exercise that compares with a golden says the goldens' size (320x240), or its command fails with
# "image sizes differ".
for page in "$root"/docs/[0-9][0-9]_*.md; do
  section=$(awk '/^## Exercises/ { e = 1; next } /^## / { e = 0 } e' "$page")
  if grep -q 'tests/golden/' <<<"$section" && ! grep -q -- '--size 320x240' <<<"$section"; then
    echo "FAIL $(basename "$page"): its exercises compare with goldens without saying --size 320x240"
    status=1
  fi
done
# Each chapter page from 03 on lists its keys: M (compare with forward) and every key of its own in
# the key table (common/platform/keys.c, through tools/key_table when the caller gives it).
if [ -n "${KEY_TABLE:-}" ]; then
  for page in "$root"/docs/[0-9][0-9]_*.md; do
    n=$(basename "$page" | cut -c1-2)
    [ "$n" -lt 3 ] && continue
    keys=$(awk '/^Keys/ { k = 1 } k { print } k && /^$/ { exit }' "$page" | tr '\n' ' ')
    own=$("$KEY_TABLE" | awk -F'|' -v n=" $n " '$3 == n { gsub(/[` ]/, "", $2); print $2 }')
    for key in M $own; do
      if ! grep -qE -- "\*\*([^*]* )?$key( [^*]*)?\*\*|[ (]$key [a-z]" <<<"$keys"; then
        echo "FAIL $(basename "$page"): its Keys paragraph does not name $key"
        status=1
      fi
    done
  done
fi
exit $status
