# Chapter 17 (screen-space ambient occlusion on chapter 11's clustered deferred frame): the pictures its
# page shows, the claim "forward gets it too" (a depth-normal pre-pass feeding the same two passes: the
# same picture), that off it is chapter 11's picture, and that on it changes the picture
# (docs/17_ssao.md). Its reference against traced rays is tests/ssao/ssao.cmake.
#
# Agreement bound: 1/255 on 99.99 % of pixels, as for chapter 11. The occlusion itself is the same to
# the byte (agree.17_ao_forward_*: forward's pre-pass writes the normal in the compact G-buffer's
# encoding and its depth with the same vertex shader, so the two passes read the same bits); what is
# left is chapter 11's own difference between the G-buffer's and the rasteriser's surface.

function(chapter_17_tests)
  set(S ${CMAKE_SOURCE_DIR}/tests/scenes)
  set(A ${CMAKE_SOURCE_DIR}/assets/scenes)
  set(C 17_ssao)
  if(NOT TARGET ${C} OR NOT TARGET 11_clustered)
    return()
  endif()

  # The pictures the page shows (the default scene's lit picture is golden.17_ssao): the raw and the
  # blurred occlusion, the reference scene, and the exercises' pictures.
  course_golden_test(17_ssao_ao ${C} 1 0.0001 --view ao)
  course_golden_test(17_ssao_ao_blurred ${C} 1 0.0001 --view ao-blurred)
  course_golden_test(17_ssao_boxes ${C} 1 0.0001 --view ao-blurred --scene ${S}/ssao_boxes.scene)
  course_golden_test(17_ssao_samples4 ${C} 1 0.0001 --view ao --ao-samples 4 --ao-blur 0)
  # Exercise 1's targets: the same 4 directions blurred over 2 x 2 and 4 x 4 pixels (the noise tile's
  # size: the pattern goes). The standard depth's picture is kept too: the golden before the
  # chapter's reversed-Z default, to the byte (that default moved one pixel, (154,138), by 63/255).
  course_golden_test(17_ssao_samples4_blur1 ${C} 1 0.0001 --view ao-blurred --ao-samples 4 --ao-blur 1)
  course_golden_test(17_ssao_samples4_blur2 ${C} 1 0.0001 --view ao-blurred --ao-samples 4 --ao-blur 2)
  course_golden_test(17_ssao_samples4_compact ${C} 1 0.0001 --view ao --ao-samples 4 --ao-blur 0
    --gbuffer compact)
  course_golden_test(17_ssao_radius2 ${C} 1 0.0001 --view ao-blurred --ao-radius 2)

  # Forward gets it too: with SSAO on, deferred and forward (and Forward+) agree on the lit picture,
  # and the occlusion they read is the same to the byte.
  foreach(case "default|" "spots|--scene@${A}/spots.scene" "teapots_cutoff0|--scene@${A}/teapots.scene@--cutoff@0"
               "boxes|--scene@${S}/ssao_boxes.scene" "800|--size@800x600")
    course_case("${case}" name args)
    course_agreement_test(17_vs_forward_${name} 1 0.0001 ${C} ${args} VS ${C} --renderer forward ${args})
  endforeach()
  # Teapots at the default cut-off, with the chapter's default reversed-Z depth: measured 0 pixels over
  # 1/255 on llvmpipe. With the standard depth (--gbuffer compact) 8 pixels of 76,800 (0.0104 %, max
  # 7/255 at (37,73)) sit on a light's hard cut-off, the pixels chapters 11 and 15 leave there: the
  # position rebuilt from a window depth near 1 is about 1e-4 units off, and falls on the other side
  # of the light's radius (agree.17_compact_vs_forward_teapots shows them; docs/17_ssao.md).
  course_agreement_test(17_vs_forward_teapots 1 0.0001 ${C} --scene ${A}/teapots.scene VS ${C} --renderer forward
    --scene ${A}/teapots.scene)
  course_agreement_test(17_compact_vs_forward_teapots 1 0.0001 ${C} --gbuffer compact --scene ${A}/teapots.scene VS
    ${C} --renderer forward --scene ${A}/teapots.scene)
  set_tests_properties(agree.17_compact_vs_forward_teapots PROPERTIES PASS_REGULAR_EXPRESSION
    "over_tol=[1-9] .*-> FAIL")
  course_agreement_test(17_vs_forward_plus 1 0.0001 ${C} VS ${C} --renderer forward-plus)
  # Chapter 18's metallic-roughness scenes (their G-buffer layout is the runner's choice for them,
  # gbuffer_layout_for_scene): forward's pre-pass is the geometry pass's own shader, so it writes the
  # normal in that layout's encoding, normal maps applied, and the occlusion stays the same to the
  # byte. Measured on llvmpipe: 1 (ibl_pbr) and 5 (pbr_teapots) pixels of 76,800 over 1/255, at most
  # 2/255: chapter 18's own difference, within the course's 0.01 %. (Before forward's pre-pass took the
  # layout's encoding it wrote compact's 12-bit codes, without normal maps: the occlusion differed on
  # 36 % of ibl_pbr's pixels, by up to 36/255.)
  foreach(case "pbr|--scene@${S}/ibl_pbr.scene" "pbr_teapots|--scene@${A}/pbr_teapots.scene")
    course_case("${case}" name args)
    course_agreement_test(17_vs_forward_${name} 1 0.0001 ${C} ${args} VS ${C} --renderer forward ${args})
    course_agreement_test(17_ao_forward_${name} 0 0 ${C} --view ao-blurred ${args} VS ${C} --renderer forward
      --view ao-blurred ${args})
  endforeach()
  foreach(case "default|" "teapots|--scene@${A}/teapots.scene" "raw|--view@ao")
    course_case("${case}" name args)
    course_agreement_test(17_ao_forward_${name} 0 0 ${C} --view ao-blurred ${args} VS ${C} --renderer forward
      --view ao-blurred ${args})
  endforeach()

  # Off, it is chapter 11's picture to the byte (with 11's --gbuffer reversed-z, this chapter's default
  # layout; with --gbuffer compact, 11's default); on, it is not (the ambient term is darker in the
  # creases: the reference scene's ambient is bright enough to show it).
  course_agreement_test(17_off_is_11 0 0 ${C} --ssao off VS 11_clustered --gbuffer reversed-z)
  course_agreement_test(17_off_compact_is_11 0 0 ${C} --ssao off --gbuffer compact VS 11_clustered)
  course_agreement_test(17_on_differs 1 0.0001 ${C} --scene ${S}/ssao_boxes.scene VS 11_clustered
    --scene ${S}/ssao_boxes.scene)
  set_tests_properties(agree.17_on_differs PROPERTIES PASS_REGULAR_EXPRESSION "imgdiff: max=[1-9][0-9]+ .*-> FAIL")

  # Chapter 14's shadows (--shadows N, docs/17_ssao.md "Shadows"): chapter 11's programs with both
  # defines. Deferred against forward on the teapots (measured on llvmpipe at 320 x 240: 7 pixels of
  # 76,800 over 1/255, 0.0091 %, max 7/255 at (37,73): the hard cut-off's pixels of
  # 17_vs_forward_teapots, 8 there, 7 here, within the course's 0.01 %); with the occlusion off it is
  # chapter 14's picture to the byte (the same programs but for the occlusion's define, which then
  # reads 1); and shadows change the picture.
  if(TARGET 14_shadows)
    set(SH --shadows 80 --scene ${A}/teapots.scene)
    course_agreement_test(17_shadows_vs_forward_teapots 1 0.0001 ${C} ${SH} VS ${C} --renderer forward ${SH})
    course_agreement_test(17_shadows_ssao_off_is_14 0 0 ${C} --ssao off --gbuffer compact ${SH} VS 14_shadows ${SH})
    course_agreement_test(17_shadows_ssao_off_is_14_default 0 0 ${C} --ssao off --gbuffer compact --shadows 8 VS
      14_shadows --shadows 8)
    course_agreement_test(17_shadows_differ 1 0.0001 ${C} ${SH} VS ${C} --scene ${A}/teapots.scene)
    set_tests_properties(agree.17_shadows_differ PROPERTIES PASS_REGULAR_EXPRESSION "imgdiff: max=[1-9][0-9]+ .*-> FAIL")
  endif()

  # --bench names the two passes beside the lighting pass.
  add_test(NAME chapters.17_bench_passes COMMAND ${C} --headless --size 160x120 --frames 1 --warmup 0 --bench
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.17_bench_passes PROPERTIES LABELS golden SKIP_RETURN_CODE 77
    PASS_REGULAR_EXPRESSION " ssao_ms=[0-9.]+ ssao_blur_ms=[0-9.]+ lighting_ms=[0-9.]+ ")

  add_test(NAME chapters.17_bad_samples COMMAND ${C} --headless --ao-samples 65 WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.17_bad_samples PROPERTIES LABELS golden
    PASS_REGULAR_EXPRESSION "bad --ao-samples '65': expected a whole number from 1 to 64")
endfunction()
chapter_17_tests()
