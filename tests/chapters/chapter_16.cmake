# Chapter 16 (the visibility buffer: a triangle id per pixel, the triangle fetched and intersected in
# one full-screen shading pass): the pictures its page shows, the claim "this is chapter 00's
# picture", its hard cases (a triangle seen edge-on, one clipped by the near plane, sub-pixel
# triangles), the id's limits, and the passes --bench names (docs/16_visibility_buffer.md).
#
# Agreement bound: 1/255 on 99.99 % of pixels, as for chapter 11, whose cluster lists the chapter
# shades with. No G-buffer rounds anything here: the position and the normal are interpolated again
# from the triangle's vertices (float), so what is left is the ray's hit against the rasterizer's
# own interpolation, and the light cut-off's step where they fall on either side of the radius
# (teapots: 1 pixel of 76,800, 4/255, as in chapters 11 and 15).

function(chapter_16_tests)
  set(S ${CMAKE_SOURCE_DIR}/tests/scenes)
  set(A ${CMAKE_SOURCE_DIR}/assets/scenes)
  set(C 16_visibility_buffer)
  if(NOT TARGET ${C} OR NOT TARGET 00_forward)
    return()
  endif()

  # The pictures the page shows (the default scene's is golden.16_visibility_buffer, with every
  # chapter's): the ids, a colour per (object, triangle).
  course_golden_test(16_visibility_buffer_ids ${C} 1 0.0001 --view ids)

  # The chapter's claim, and its hard cases:
  #   edge_on   the red box's top face (y = 1) 2 mm below the eye: triangles seen almost edge-on, a
  #             pixel tall, where the ray meets the plane at a grazing angle (det near 0)
  #   near      the box's front face 0.1 in front of the eye, near plane 0.3: the rasterizer draws
  #             the clipped polygon, the shading pass intersects the whole triangle
  foreach(case "default|" "spots|--scene@${A}/spots.scene" "teapots|--scene@${A}/teapots.scene"
               "time3|--time@3" "800|--size@800x600"
               "edge_on|--camera@eye -1.6 1.002 4 target -1.6 1.002 -0.8"
               "near|--scene@${S}/near_plane.scene@--camera@eye 0.45 0.7 1.6 target -1 0.5 0 near 0.3")
    course_case("${case}" name args)
    course_agreement_test(16_vs_forward_${name} 1 0.0001 ${C} ${args} VS 00_forward ${args})
  endforeach()

  # Textures (chapter 18's textured metallic-roughness teapots): the shading pass rebuilds the texture
  # coordinate and its screen derivatives from the triangle and reads the images with textureGrad,
  # through samplers without anisotropy (llvmpipe ignores explicit derivatives on an anisotropic
  # texture); forward reads them the same way with --anisotropy 1. Measured on llvmpipe: 42 pixels of
  # 76,800 (0.055 %) over 1/255, at most 13/255, on the gold and copper teapots' hammered dimples and
  # silhouettes, where the narrow GGX highlight magnifies the rebuilt normal's and texture
  # coordinate's last bits through the normal map (60 with --cutoff 0: not the cut-off; 17, 0.022 %,
  # before the teapots had texture coordinates and images); with every image read at level 0
  # instead it is thousands. At the default anisotropy (8) forward
  # filters along the footprint and the chapter does not: 9.5 % of pixels differ, up to 94/255 on
  # the far floor (agree.16_pbr_aniso_differs fails the 1/255 comparison, as it must).
  set(PBR --scene ${A}/pbr_teapots.scene)
  course_agreement_test(16_vs_forward_pbr 1 0.0006 ${C} ${PBR} --anisotropy 1 VS ${C} --renderer forward ${PBR}
    --anisotropy 1)
  course_agreement_test(16_pbr_aniso_differs 1 0.0001 ${C} ${PBR} VS ${C} --renderer forward ${PBR})
  set_tests_properties(agree.16_pbr_aniso_differs PROPERTIES PASS_REGULAR_EXPRESSION "imgdiff: max=[1-9][0-9]+ .*-> FAIL")

  # Sub-pixel triangles: 125 bunnies (7.3 million triangles) at 160 x 120, most triangles smaller
  # than a pixel. Measured on llvmpipe: 5 pixels of 19,200 (0.026 %) over 1/255, at most 3/255:
  # the ray's hit and the rasterizer's interpolation of a sliver differ in the last bits. The
  # bounds are the measurement: more is a new bug.
  set(BUNNIES --scene ${A}/bunnies.scene --size 160x120)
  course_agreement_test(16_bunnies_max 3 0 ${C} ${BUNNIES} VS 00_forward ${BUNNIES})
  course_agreement_test(16_bunnies_count 1 0.0003 ${C} ${BUNNIES} VS 00_forward ${BUNNIES})

  # --samples 4, ids per sample, against chapter 13's forward MSAA at the same sample count (the
  # same resolve: linear radiance averaged, then display-encoded). Edge pixels shade each sample's
  # triangle where forward MSAA shades it (the pixel centre, extrapolated). Measured on llvmpipe,
  # 320 x 240: default and spots at most 1/255; teapots 1 pixel at 4/255 and the city 8 pixels of
  # 76,800 (0.0104 %) at most 3/255, the light cut-off's step as in chapters 11 and 13 (whose city
  # bound this is); the bunnies at 160 x 120 4 pixels (0.021 %) at most 5/255, the slivers' last bits
  # as at 1 sample. The bounds are the measurement.
  if(TARGET 13_msaa)
    set(M4 --renderer forward --samples 4)
    course_agreement_test(16_msaa4_vs_13 1 0.0001 ${C} --samples 4 VS 13_msaa ${M4})
    course_agreement_test(16_msaa4_vs_13_spots 1 0.0001 ${C} --samples 4 --scene ${A}/spots.scene
                          VS 13_msaa ${M4} --scene ${A}/spots.scene)
    course_agreement_test(16_msaa4_vs_13_teapots 1 0.0001 ${C} --samples 4 --scene ${A}/teapots.scene
                          VS 13_msaa ${M4} --scene ${A}/teapots.scene)
    course_agreement_test(16_msaa4_vs_13_city 1 0.00015 ${C} --samples 4 --scene ${A}/city.scene
                          VS 13_msaa ${M4} --scene ${A}/city.scene)
    course_agreement_test(16_msaa4_bunnies_max 5 0 ${C} --samples 4 ${BUNNIES} VS 13_msaa ${M4} ${BUNNIES})
    course_agreement_test(16_msaa4_bunnies_count 1 0.0003 ${C} --samples 4 ${BUNNIES} VS 13_msaa ${M4} ${BUNNIES})
    # --samples 1 is the chapter's own picture (the MSAA path is off)
    course_agreement_test(16_samples1 0 0 ${C} --samples 1 VS ${C})
  endif()

  # The forward renderer the chapter offers is chapter 00's, to the byte.
  course_agreement_test(16_renderer_forward 0 0 ${C} --renderer forward VS 00_forward)

  # Chapter 14's shadows (--shadows N, docs/16_visibility_buffer.md "Shadows"): the shading pass's
  # cluster loop reads the atlas at the rebuilt surface, forward at the rasterised one: the same picture
  # within the chapter's bound (measured on llvmpipe at 320 x 240: 2 pixels of 76,800 over 1/255
  # on the teapots, max 4/255); forward itself is chapter 14's, to the byte; and shadows change the picture.
  if(TARGET 14_shadows)
    set(SH --shadows 80 --scene ${A}/teapots.scene)
    course_agreement_test(16_shadows_vs_forward_teapots 1 0.0001 ${C} ${SH} VS ${C} --renderer forward ${SH})
    course_agreement_test(16_shadows_forward_is_14 0 0 ${C} --renderer forward ${SH} VS 14_shadows --renderer forward ${SH})
    course_agreement_test(16_shadows_differ 1 0.0001 ${C} ${SH} VS ${C} --scene ${A}/teapots.scene)
    set_tests_properties(agree.16_shadows_differ PROPERTIES PASS_REGULAR_EXPRESSION "imgdiff: max=[1-9][0-9]+ .*-> FAIL")
  endif()

  # The id's limits: 4,095 objects and 2^20 triangles a mesh drawn; one more refused at load (exit 2).
  add_test(NAME chapters.16_id_limits
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/chapters/run_vis_limits.sh $<TARGET_FILE:${C}>
            ${COURSE_TEST_OUT}/16_id_limits
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.16_id_limits PROPERTIES LABELS golden SKIP_RETURN_CODE 77)

  # --vis-pass (docs/16_visibility_buffer.md, "What it costs"): full is the chapter's picture to the
  # byte, at 1 and 4 samples; the two timing modes draw other pictures on purpose. no-primitive-id
  # shades every pixel of an object as its first triangle: the lit picture and the ids view differ
  # from full's. depth-only writes no id: its lit picture is its ids view, the background alone
  # (were ids drawn, the one would be shaded and the other hashed colours). run_vis_pass.sh: every
  # mode's --bench line, its warning, the pixels it shades (depth-only none), a bad mode (exit 2).
  course_agreement_test(16_vis_pass_full 0 0 ${C} --vis-pass full VS ${C})
  course_agreement_test(16_vis_pass_full_msaa4 0 0 ${C} --samples 4 --vis-pass full VS ${C} --samples 4)
  course_agreement_test(16_vis_pass_no_primitive_id_differs 1 0.0001 ${C} --vis-pass no-primitive-id VS ${C})
  course_agreement_test(16_vis_pass_no_primitive_id_ids_differ 1 0.0001 ${C} --view ids --vis-pass no-primitive-id
                        VS ${C} --view ids)
  set_tests_properties(agree.16_vis_pass_no_primitive_id_differs agree.16_vis_pass_no_primitive_id_ids_differ
    PROPERTIES PASS_REGULAR_EXPRESSION "imgdiff: max=[1-9][0-9]+ .*-> FAIL")
  course_agreement_test(16_vis_pass_depth_only_background 0 0 ${C} --vis-pass depth-only
                        VS ${C} --vis-pass depth-only --view ids)
  course_agreement_test(16_vis_pass_depth_only_background_msaa4 0 0 ${C} --samples 4 --vis-pass depth-only
                        VS ${C} --samples 4 --vis-pass depth-only --view ids)
  add_test(NAME chapters.16_vis_pass
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/chapters/run_vis_pass.sh $<TARGET_FILE:${C}>
            ${COURSE_TEST_OUT}/16_vis_pass
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.16_vis_pass PROPERTIES LABELS golden SKIP_RETURN_CODE 77)

  # --bench names the three passes; with --samples 4 the fourth, the edges shaded per sample.
  add_test(NAME chapters.16_bench_passes_msaa
    COMMAND ${C} --headless --size 160x120 --frames 1 --warmup 0 --bench --samples 4
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.16_bench_passes_msaa PROPERTIES LABELS golden SKIP_RETURN_CODE 77
    PASS_REGULAR_EXPRESSION " visibility_pass_ms=[0-9.]+ light_assignment_ms=[0-9.]+ shading_ms=[0-9.]+ shading_edges_ms=[0-9.]+ ")
  add_test(NAME chapters.16_bench_passes COMMAND ${C} --headless --size 160x120 --frames 1 --warmup 0 --bench
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.16_bench_passes PROPERTIES LABELS golden SKIP_RETURN_CODE 77
    PASS_REGULAR_EXPRESSION " visibility_pass_ms=[0-9.]+ light_assignment_ms=[0-9.]+ shading_ms=[0-9.]+ ")
endfunction()
chapter_16_tests()
