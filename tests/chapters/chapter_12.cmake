# Chapter 12 (transparency: glass shaded forward, back to front, over the deferred frame): the
# pictures its page shows, the claim "this matches forward" with glass and without, that the order
# matters, that the glass stays out of the G-buffer, and the hard cases (docs/12_transparency.md).
#
# Agreement bound: 1/255 on 99.99 % of pixels, as for chapter 11 (the same G-buffer and cluster
# lists; the glass is the same draws in the same order, blended in linear radiance on both sides: into
# the RGBA32F target here, into forward's RGBA32F frame there; its lights come from its cluster's list
# here and from its object's list there, and a light on neither list adds exactly 0).

function(chapter_12_tests)
  set(S ${CMAKE_SOURCE_DIR}/tests/scenes)
  set(GLASS ${CMAKE_SOURCE_DIR}/assets/scenes/glass.scene)
  set(C 12_transparency)
  if(NOT TARGET ${C} OR NOT TARGET 00_forward)
    return()
  endif()

  # The pictures the page shows: the glass scene lit, in the scene's order (the bug), its glass
  # layers as a heat map, the opaque part alone; the camera inside a glass ball; panes at equal depths.
  course_golden_test(12_transparency_glass ${C} 1 0.0001 --scene ${GLASS})
  course_golden_test(12_transparency_glass_sort_none ${C} 1 0.0001 --scene ${GLASS} --sort none)
  course_golden_test(12_transparency_glass_overdraw ${C} 1 0.0001 --scene ${GLASS} --view overdraw)
  course_golden_test(12_transparency_glass_inside ${C} 1 0.0001 --scene ${S}/glass_inside.scene)
  course_golden_test(12_transparency_glass_same_depth ${C} 1 0.0001 --scene ${S}/glass_same_depth.scene)

  # The chapter's claim: chapter 00's picture, on the default scene (no glass: chapter 07's frame) and
  # on the glass scene, moving, from the other side (the sort follows the eye), at other cut-offs, with
  # the windowed falloff, with generated lights, at full size; and on the hard cases.
  course_forward_agreement_test(12_vs_forward 1 0.0001 ${C})
  foreach(case "glass|" "glass_time3|--time@3" "glass_behind|--camera@eye -4 3.5 -6 target 0.3 0.8 0"
               "glass_cutoff0|--cutoff@0" "glass_cutoff0.1|--cutoff@0.1" "glass_windowed|--falloff@windowed"
               "glass_800|--size@800x600")
    course_case("${case}" name args)
    course_forward_agreement_test(12_vs_forward_${name} 1 0.0001 ${C} --scene ${GLASS} ${args})
  endforeach()
  # 64 generated lights: the opaque part's cut-off steps as in agree.07_vs_forward_lights64 (the same
  # 3 pixels, max 9/255, none of them under glass), hence its bound of 0.02 %.
  course_forward_agreement_test(12_vs_forward_glass_lights64 1 0.0002 ${C} --scene ${GLASS} --lights 64)
  foreach(scene glass_inside glass_same_depth)
    course_forward_agreement_test(12_vs_forward_${scene} 1 0.0001 ${C} --scene ${S}/${scene}.scene)
  endforeach()
  course_agreement_test(12_renderer_forward 0 0 ${C} --renderer forward --scene ${GLASS}
    VS 00_forward --scene ${GLASS})

  # Forward+ draws the glass too, with the cluster lists (clusters_shade_glass) where forward uses its
  # per-object lists: a light on neither list adds exactly 0 and both lists are in light order, so
  # the sums, and the pictures, are the same to the byte (measured on these scenes).
  foreach(case "glass|--scene@${GLASS}" "glass_lights64|--scene@${GLASS}@--lights@64"
               "glass_inside|--scene@${S}/glass_inside.scene" "glass_same_depth|--scene@${S}/glass_same_depth.scene")
    course_case("${case}" name args)
    course_agreement_test(00_forward_plus_${name} 0 0
      00_forward --renderer forward-plus ${args} VS 00_forward --renderer forward ${args})
  endforeach()
  course_agreement_test(12_forward_plus_glass 0 0 ${C} --renderer forward-plus --scene ${GLASS}
    VS 00_forward --scene ${GLASS})

  # The order matters: drawn in the scene's order (nearest first) the glass is not forward's picture.
  course_agreement_test(12_sort_none_differs 1 0.0001 ${C} --scene ${GLASS} --sort none VS 00_forward --scene ${GLASS})
  set_tests_properties(agree.12_sort_none_differs PROPERTIES PASS_REGULAR_EXPRESSION "imgdiff: max=[1-9][0-9]+ .*-> FAIL")

  # The glass is in no G-buffer: the glass scene is the default scene plus glass, and chapter 02's
  # G-buffer views of both are the same bytes; chapter 11, which has no glass pass, draws the same
  # frame for both; and chapter 12's opaque view is chapter 11's frame, byte for byte (the lighting
  # pass's linear radiance is stored as 32-bit floats, and the present pass applies the same
  # display_encode to the same values).
  if(TARGET 02_mrt_gbuffer)
    foreach(view depth albedo normal specular)
      course_agreement_test(12_glass_not_in_gbuffer_${view} 0 0
        02_mrt_gbuffer --scene ${GLASS} --view ${view} VS 02_mrt_gbuffer --view ${view})
    endforeach()
  endif()
  if(TARGET 11_clustered)
    course_agreement_test(12_chapter_11_draws_no_glass 0 0 11_clustered --scene ${GLASS} VS 11_clustered)
    course_agreement_test(12_opaque_view_is_11 0 0 ${C} --scene ${GLASS} --view opaque VS 11_clustered)
    course_agreement_test(12_default_is_11 0 0 ${C} VS 11_clustered)
    course_agreement_test(12_default_is_11_lights1024 0 0 ${C} --lights 1024 VS 11_clustered --lights 1024)
  endif()

  # Chapter 00's optimisations still change nothing with glass (the pre-pass leaves it out; the
  # variants without a pre-pass write the opaque depth while shading), nor does chapter 01's
  # framebuffer (its depth is a renderbuffer: forward copies it in and out).
  foreach(variant forward-naive forward-prepass forward-lists)
    course_agreement_test(00_${variant}_glass 1 0.0001
      00_forward --renderer forward --scene ${GLASS} VS 00_forward --renderer ${variant} --scene ${GLASS})
  endforeach()
  if(TARGET 01_fbo_setup)
    course_agreement_test(01_offscreen_glass 0 0 01_fbo_setup --scene ${GLASS} VS 00_forward --scene ${GLASS})
  endif()

  # The heat map counts exactly the glass pass's fragments (its GL_SAMPLES_PASSED, --bench's
  # shaded_pixels), in the lit view too; and the check is not vacuous (another scene's count).
  if(TARGET heat_count)
    foreach(case "glass|--scene@${GLASS}" "inside|--scene@${S}/glass_inside.scene"
                 "same_depth|--scene@${S}/glass_same_depth.scene")
      course_case("${case}" name args)
      course_overdraw_count_test(12_sum_${name} lit-run $<TARGET_FILE:${C}> ${COURSE_RENDER_ARGS} ${args})
    endforeach()
    course_overdraw_count_test(12_other_scene_differs lit-run
      $<TARGET_FILE:${C}> ${COURSE_RENDER_ARGS} --scene ${GLASS} -- --scene ${S}/glass_inside.scene)
    set_tests_properties(overdraw.12_other_scene_differs PROPERTIES
      PASS_REGULAR_EXPRESSION "\\(expected sum [0-9]+\\) -> FAIL")
  endif()

  # Resizes with glass: forward's float frame and chapter 12's buffers follow the size, leak nothing.
  foreach(chapter ${C} 00_forward)
    add_test(NAME robust.resize_cycle_glass.${chapter}
      COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/golden/run_agreement.sh $<TARGET_FILE:imgdiff>
              ${CMAKE_BINARY_DIR}/test-out resize_cycle_glass.${chapter} 1 0.0001
              -- $<TARGET_FILE:${chapter}> --headless --size 128x96 --frames 1 --gl-debug --scene ${GLASS}
                 --resize-cycle 50
              -- $<TARGET_FILE:${chapter}> --headless --size 128x96 --frames 1 --gl-debug --scene ${GLASS}
      WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
    set_tests_properties(robust.resize_cycle_glass.${chapter} PROPERTIES LABELS robust SKIP_RETURN_CODE 77
      FAIL_REGULAR_EXPRESSION "still alive at exit")
  endforeach()

  add_test(NAME chapters.12_bad_sort COMMAND ${C} --headless --sort front-to-back
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.12_bad_sort PROPERTIES LABELS golden
    PASS_REGULAR_EXPRESSION "unknown --sort value 'front-to-back' \\(one of: back-to-front none\\)")
endfunction()
chapter_12_tests()

# Chapters 09 and 12 open on their lesson's scene when --scene is not given: the spots and the glass,
# the goldens those scenes give with --scene named.
foreach(pair "09_spot_lights|09_spot_lights_spots" "12_transparency|12_transparency_glass")
  string(REPLACE "|" ";" pair "${pair}")
  list(GET pair 0 chapter)
  list(GET pair 1 golden)
  if(TARGET ${chapter})
    add_test(NAME golden.${chapter}_opens_on_its_scene
      COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/golden/run_golden.sh $<TARGET_FILE:imgdiff> ${COURSE_TEST_OUT}
              ${chapter}_opens_on_its_scene ${CMAKE_SOURCE_DIR}/tests/golden/${golden}.png 1 0.0001
              -- $<TARGET_FILE:${chapter}> --headless --size ${COURSE_GOLDEN_SIZE} --frames 1 --gl-debug
      WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
    set_tests_properties(golden.${chapter}_opens_on_its_scene PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
  endif()
endforeach()

# A chapter that cannot draw glass says so once, on stderr (11 and 13 build on the G-buffer, which
# holds no glass); chapter 12, which draws it, says nothing.
if(TARGET 11_clustered AND TARGET 13_msaa AND TARGET 12_transparency)
  add_test(NAME chapters.glass_left_out_said
    COMMAND ${BASH} -c "for c in $<TARGET_FILE:11_clustered> $<TARGET_FILE:13_msaa>; do \
        err=$($c --headless --size 160x120 --frames 3 --scene assets/scenes/glass.scene 2>&1 >/dev/null); rc=$?; \
        [ $rc -eq 77 ] && exit 77; \
        [ $(grep -c 'glass object(s) are not drawn' <<<\"$err\") -eq 1 ] || { echo \"FAIL $c: $err\"; exit 1; }; done; \
      err=$($<TARGET_FILE:12_transparency> --headless --size 160x120 --scene assets/scenes/glass.scene 2>&1 >/dev/null); \
      grep -q 'glass' <<<\"$err\" && { echo \"FAIL 12 warned: $err\"; exit 1; }; echo ok: said once by 11 and 13, not by 12"
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.glass_left_out_said PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
endif()
