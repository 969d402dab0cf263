# The debug views of chapters 03-07 (key V, common/render/debug_views.h): `overdraw`, the lighting
# fragments per pixel as a heat map (shaders/heat.glsl), and `volumes`, the light volumes as lines.
# Goldens for the pictures the pages show; then the heat map read back into counts
# (tools/heat_count.c, tests/golden/run_overdraw_count.sh) and checked against GL_SAMPLES_PASSED, the
# count --bench prints as shaded_pixels: the picture is only right if every pixel's count is.
# The lit views are unchanged: their goldens (chapters_01_03.cmake, chapters_04_07.cmake) still hold.

function(debug_views_tests)
  if(NOT TARGET heat_count)
    return()
  endif()
  set(S ${CMAKE_SOURCE_DIR}/tests/scenes)
  # The colour scale itself, as the pages show it: counts 0..16, one 20-pixel swatch each
  # (update-goldens does not write it: build/bin/heat_count --legend tests/golden/heat_scale.png).
  add_test(NAME golden.heat_scale
    COMMAND ${BASH} -c "\"$0\" --legend \"$1\" && \"$2\" \"$3\" \"$1\""
            $<TARGET_FILE:heat_count> ${COURSE_TEST_OUT}/heat_scale.png $<TARGET_FILE:imgdiff>
            ${CMAKE_SOURCE_DIR}/tests/golden/heat_scale.png)
  set_tests_properties(golden.heat_scale PROPERTIES LABELS golden SKIP_RETURN_CODE 77)

  if(TARGET 03_fullscreen_phong)
    course_golden_test(03_fullscreen_phong_overdraw 03_fullscreen_phong 1 0.0001 --view overdraw)
    course_golden_test(03_fullscreen_phong_volumes 03_fullscreen_phong 1 0.0001 --view volumes --cutoff 0.3)
    # The loop evaluates every active light at every covered pixel, whatever the cut-off: 8 lights,
    # then 12 generated ones at a cut-off where most of them reach little.
    course_overdraw_count_test(03_every_light loop $<TARGET_FILE:03_fullscreen_phong> ${COURSE_RENDER_ARGS})
    course_overdraw_count_test(03_every_light_12 loop
      $<TARGET_FILE:03_fullscreen_phong> ${COURSE_RENDER_ARGS} --lights 12 --cutoff 0.1)
    # 20 lights: past the scale's end every covered pixel is the saturated colour, which
    # heat_count refuses to read as an exact count.
    course_overdraw_count_test(03_saturates loop $<TARGET_FILE:03_fullscreen_phong> ${COURSE_RENDER_ARGS} --lights 20)
    set_tests_properties(overdraw.03_saturates PROPERTIES
      PASS_REGULAR_EXPRESSION "max=16 saturated=([1-9][0-9]*) unreadable=0 counts 0:[0-9]+ 16:[0-9]+ .*-> FAIL")
  endif()

  if(TARGET 04_light_volumes)
    course_golden_test(04_light_volumes_overdraw 04_light_volumes 1 0.0001 --view overdraw)
    course_golden_test(04_light_volumes_volumes 04_light_volumes 1 0.0001 --view volumes)
    # Chapter 04's lit pass discards outside the fixed radius after running: its own shaded_pixels
    # is smaller, so the heat map is checked against the counting pass (same faces, no depth test).
    course_overdraw_count_test(04_sum same-run $<TARGET_FILE:04_light_volumes> ${COURSE_RENDER_ARGS})
    course_overdraw_count_test(04_sum_unscaled same-run
      $<TARGET_FILE:04_light_volumes> ${COURSE_RENDER_ARGS} --scale none --radius 2)
  endif()

  if(TARGET 05_attenuation_radius)
    course_golden_test(05_attenuation_radius_overdraw 05_attenuation_radius 1 0.0001
      --view overdraw --cutoff 0.3)
    # At 0.3 some volumes are finite, some cover the view (full-screen triangles): both counted.
    course_overdraw_count_test(05_sum same-run $<TARGET_FILE:05_attenuation_radius> ${COURSE_RENDER_ARGS} --cutoff 0.3)
  endif()

  if(TARGET 06_additive_blending)
    course_golden_test(06_additive_blending_overdraw 06_additive_blending 1 0.0001 --view overdraw --cutoff 0.1)
    # No depth test, no discard: every fragment of every back face runs, background included.
    course_overdraw_count_test(06_sum lit-run $<TARGET_FILE:06_additive_blending> ${COURSE_RENDER_ARGS})
    course_overdraw_count_test(06_sum_cutoff lit-run
      $<TARGET_FILE:06_additive_blending> ${COURSE_RENDER_ARGS} --cutoff 0.1)
  endif()

  if(TARGET 07_face_culling)
    course_golden_test(07_face_culling_volumes 07_face_culling 1 0.0001 --view volumes --cutoff 0.3)
    # The heat map counts exactly the fragments chapter 07's lighting pass runs, for each of its
    # pass states (--cull, --depth-clamp) and with full-screen lights.
    foreach(case "default|" "cutoff_0.1|--cutoff@0.1" "cull_none|--cutoff@0.1@--cull@none"
                 "cull_back|--cutoff@0.1@--cull@back" "far_no_clamp|--scene@${S}/far_plane.scene@--depth-clamp@off"
                 "inside|--scene@${S}/inside_volume.scene")
      course_case("${case}" name args)
      course_overdraw_count_test(07_sum_${name} lit-run $<TARGET_FILE:07_face_culling> ${COURSE_RENDER_ARGS} ${args})
    endforeach()
    # The check is not vacuous: the picture of --cull none against the lit pass of --cull front.
    course_overdraw_count_test(07_other_state_differs lit-run
      $<TARGET_FILE:07_face_culling> ${COURSE_RENDER_ARGS} --cutoff 0.1 --cull none -- --cull front)
    set_tests_properties(overdraw.07_other_state_differs PROPERTIES
      PASS_REGULAR_EXPRESSION "\\(expected sum [0-9]+\\) -> FAIL")
  endif()

  if(TARGET 03_fullscreen_phong AND TARGET 07_face_culling)
    # Chapter 03's spheres are the volume chapters' meshes at the same radii: the same lines over
    # the same picture (the lit parts agree as 03 and 07 each agree with forward).
    course_agreement_test(volumes_03_vs_07 1 0.0001
      03_fullscreen_phong --view volumes --cutoff 0.3 VS 07_face_culling --view volumes --cutoff 0.3)
  endif()
endfunction()

debug_views_tests()
