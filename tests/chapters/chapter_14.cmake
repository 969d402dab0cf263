# Chapter 14 (shadows for many lights: a depth atlas, tiles by importance, culled casters, cached
# tiles): the pictures its page shows, the claim "forward and Forward+ cast the same shadows", that
# shadows start here (with none, chapter 11's picture), that culling and the cache change the work and
# never the picture, and the hard cases (docs/14_shadows.md, docs/hard-cases.md).
#
# Agreement bound: 1/255 on 99.99 % of pixels. Deferred and forward read the same atlas through the
# same shadows.glsl; their surface points differ in the last bits (the G-buffer's position from depth,
# its normal octahedral-encoded), which moves a PCF comparison across a shadow's edge on a few pixels
# (bilinear PCF taps, not snapped to texels, keep that change below a level: measured 0 pixels over on
# the default scene, 5 on the spots). A wider filter needs a larger normal offset: its outer taps fall on the
# receiver's own depth when it slopes away from the light, and a last-bit difference then flips them
# (the default scene at --pcf 5: 187 pixels over with the default 0.25 texels, 1 with 1.5), so --pcf 3
# and 5 are checked at --normal-offset 1.5 (docs/14_shadows.md, "Choosing the defaults").

function(chapter_14_tests)
  set(S ${CMAKE_SOURCE_DIR}/tests/scenes)
  set(A ${CMAKE_SOURCE_DIR}/assets/scenes)
  set(C 14_shadows)
  if(NOT TARGET ${C} OR NOT TARGET 11_clustered)
    return()
  endif()

  # The pictures the page shows (the default scene's is golden.14_shadows, with every chapter's).
  course_golden_test(14_shadows_teapots ${C} 1 0.0001 --scene ${A}/teapots.scene)
  course_golden_test(14_shadows_spots ${C} 1 0.0001 --scene ${A}/spots.scene)
  course_golden_test(14_shadows_pcf3 ${C} 1 0.0001 --pcf 3 --normal-offset 1.5)
  course_golden_test(14_shadows_visibility ${C} 1 0.0001 --scene ${S}/shadow_one_light.scene --view visibility)
  course_golden_test(14_shadows_contact ${C} 1 0.0001 --scene ${S}/shadow_contact.scene)
  # Exercise 2's pictures and its counts, performed (tests/chapters/run_shadow_exercise.sh).
  course_golden_test(14_shadows_grazing ${C} 1 0.0001 --scene ${S}/shadow_grazing.scene)
  course_golden_test(14_shadows_grazing_acne ${C} 1 0.0001 --scene ${S}/shadow_grazing.scene --normal-offset 0
    --slope-bias 0)
  add_test(NAME pages.14_exercise_2
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/chapters/run_shadow_exercise.sh $<TARGET_FILE:${C}>
            $<TARGET_FILE:imgdiff> ${COURSE_TEST_OUT}/14_exercise_2 ${S})
  set_tests_properties(pages.14_exercise_2 PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
  # The window's views of the atlas: each tile's depth in its light's tier colour, and a disc per
  # light in the same colours over the picture; the discs, counted by colour, are the plan's tiers
  # and the counts the page's caption gives (tests/chapters/run_importance_tiers.sh).
  course_golden_test(14_shadows_atlas ${C} 1 0.0001 --scene ${A}/teapots.scene --view atlas)
  course_golden_test(14_shadows_importance ${C} 1 0.0001 --scene ${A}/teapots.scene --view importance)
  add_test(NAME chapters.14_importance_tiers
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/chapters/run_importance_tiers.sh $<TARGET_FILE:${C}>
            ${COURSE_TEST_OUT}/14_importance_tiers ${A}/teapots.scene ${CMAKE_SOURCE_DIR}/docs/14_shadows.md
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.14_importance_tiers PROPERTIES LABELS golden SKIP_RETURN_CODE 77)

  # The window's K and overlay, driven by a --script: K off is chapter 11's picture and K on again
  # chapter 14's; the overlay counts the lights and tiles, and times the shadow pass on its own.
  add_test(NAME window.14_shadow_keys
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/chapters/run_shadow_keys.sh $<TARGET_FILE:imgdiff>
            ${COURSE_TEST_OUT} $<TARGET_FILE:${C}> $<TARGET_FILE:11_clustered>
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(window.14_shadow_keys PROPERTIES LABELS golden SKIP_RETURN_CODE 77)

  # Forward and Forward+ cast the same shadows: the chapter's deferred frame against its forward one,
  # and Forward+ against forward (the same sums in the same order: the same bytes).
  # Teapots: 0.02 %: chapter 11's own deferred and forward frames differ on the same 8 pixels there (max
  # 7/255 at (37,73), the G-buffer's normal on the spout's rim), shadows or not.
  course_agreement_test(14_vs_forward_teapots 1 0.0002 ${C} --scene ${A}/teapots.scene
    VS ${C} --renderer forward --scene ${A}/teapots.scene)
  course_agreement_test(14_forward_plus_teapots 0 0 ${C} --renderer forward-plus --scene ${A}/teapots.scene
    VS ${C} --renderer forward --scene ${A}/teapots.scene)
  # One bright light: 0.03 % (measured 16 pixels of 76,800, at most 6/255, on its shadows' edges, 10 with
  # --pcf 3: one bilinear comparison's edge is steeper than nine's average; chapter 11 on the same scene:
  # none).
  course_agreement_test(14_vs_forward_one_light 1 0.0003 ${C} --scene ${S}/shadow_one_light.scene
    VS ${C} --renderer forward --scene ${S}/shadow_one_light.scene)
  foreach(case "default|" "spots|--scene@${A}/spots.scene"
               "spot|--scene@${S}/shadow_spot.scene"
               "contact|--scene@${S}/shadow_contact.scene" "grazing|--scene@${S}/shadow_grazing.scene"
               "inside|--scene@${S}/shadow_inside.scene" "camera_inside|--scene@${S}/shadow_camera_inside.scene"
               "pcf3|--pcf@3@--normal-offset@1.5" "pcf5|--pcf@5@--normal-offset@1.5" "offset1.5|--normal-offset@1.5"
               "d16|--shadow-format@d16" "atlas512|--shadow-atlas@512")
    course_case("${case}" name args)
    course_agreement_test(14_vs_forward_${name} 1 0.0001 ${C} ${args} VS ${C} --renderer forward ${args})
    course_agreement_test(14_forward_plus_${name} 0 0 ${C} --renderer forward-plus ${args}
      VS ${C} --renderer forward ${args})
  endforeach()

  # Shadows start here: with none (--shadows 0) the picture is chapter 11's, byte for byte; and a
  # ground that casts, lit across every cube face's edges and corners and from closer than the near
  # plane, with nothing else to cast, is chapter 11's picture too (no seam, no acne, no false shadow).
  course_agreement_test(14_shadows0_is_11 0 0 ${C} --shadows 0 VS 11_clustered)
  course_agreement_test(14_shadows0_is_11_teapots 0 0 ${C} --shadows 0 --scene ${A}/teapots.scene
    VS 11_clustered --scene ${A}/teapots.scene)
  foreach(renderer deferred forward forward-plus)
    course_agreement_test(14_faces_is_11_${renderer} 0 0 ${C} --renderer ${renderer} --scene ${S}/shadow_faces.scene
      VS 11_clustered --renderer ${renderer} --scene ${S}/shadow_faces.scene)
  endforeach()
  # ... and with shadows the picture is not chapter 11's (the test above is not vacuous).
  course_agreement_test(14_shadows_differ_from_11 1 0.0001 ${C} VS 11_clustered)
  set_tests_properties(agree.14_shadows_differ_from_11 PROPERTIES PASS_REGULAR_EXPRESSION "imgdiff: max=[1-9][0-9]+ .*-> FAIL")

  # Culling changes the work, never the picture; the scene's `shadow off` on every light is --shadows 0.
  course_agreement_test(14_cull_off_same 0 0 ${C} --scene ${A}/teapots.scene --shadow-cull off
    VS ${C} --scene ${A}/teapots.scene)

  # The --bench line: counts, never timings. Teapots: culling leaves out casters (fewer triangles than
  # without); an atlas too small drops the least important lights, and says so; --shadows N.
  set(BENCH_ARGS --headless --size 160x120 --frames 1 --warmup 0 --bench)
  add_test(NAME chapters.14_bench_cull COMMAND ${C} ${BENCH_ARGS} --scene ${A}/teapots.scene
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.14_bench_cull PROPERTIES LABELS golden SKIP_RETURN_CODE 77
    PASS_REGULAR_EXPRESSION "shadowed=80 off=0 not_chosen=0 dropped=0 .* tiles=480 tiles_drawn=480 ")
  add_test(NAME chapters.14_bench_overflow COMMAND ${C} ${BENCH_ARGS} --shadow-atlas 512 --lights 64
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.14_bench_overflow PROPERTIES LABELS golden SKIP_RETURN_CODE 77
    PASS_REGULAR_EXPRESSION "shadowed=2 off=0 not_chosen=0 dropped=62 ")
  add_test(NAME chapters.14_bench_shadows_n COMMAND ${C} ${BENCH_ARGS} --scene ${A}/teapots.scene --shadows 16
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.14_bench_shadows_n PROPERTIES LABELS golden SKIP_RETURN_CODE 77
    PASS_REGULAR_EXPRESSION "shadowed=16 off=0 not_chosen=64 dropped=0 ")
  add_test(NAME chapters.14_bench_camera_inside COMMAND ${C} ${BENCH_ARGS} --scene ${S}/shadow_camera_inside.scene
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.14_bench_camera_inside PROPERTIES LABELS golden SKIP_RETURN_CODE 77
    PASS_REGULAR_EXPRESSION "shadowed=1 .* tier_lights=1/0/0/0 tiles=6 ")

  # Bad values: one line naming the option, exit 2.
  foreach(case "atlas_not_pow2|--shadow-atlas@3000|bad --shadow-atlas '3000': expected 256, 512,"
               "atlas_small|--shadow-atlas@64|--shadow-atlas"
               "pcf|--pcf@2|unknown --pcf value '2'"
               "format|--shadow-format@d24|unknown --shadow-format value 'd24'")
    string(REPLACE "|" ";" parts "${case}")
    list(GET parts 0 name)
    list(GET parts 1 args)
    list(GET parts 2 want)
    string(REPLACE "@" ";" args "${args}")
    add_test(NAME chapters.14_bad_${name} COMMAND ${C} --headless --size 64x48 --frames 1 ${args}
      WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
    set_tests_properties(chapters.14_bad_${name} PROPERTIES LABELS golden SKIP_RETURN_CODE 77
      PASS_REGULAR_EXPRESSION "${want}")
  endforeach()
endfunction()
chapter_14_tests()
