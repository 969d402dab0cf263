# The windowed falloff (--falloff windowed, or the scene's `falloff windowed`): the light reaches
# zero, with zero slope, at its radius, so a light volume that stops there cuts nothing off and
# every renderer draws the windowed model's own picture. Same bound as every agreement test: the
# deferred renderers differ from forward only by the G-buffer's 8-bit albedo.
if(TARGET 07_face_culling AND TARGET 00_forward AND TARGET 06_additive_blending)
  set(S ${CMAKE_SOURCE_DIR}/tests/scenes)
  foreach(cutoff 0.3 0.01953125)
    course_forward_agreement_test(07_windowed_cutoff_${cutoff} 1 0.0001
      07_face_culling --falloff windowed --cutoff ${cutoff})
  endforeach()
  course_forward_agreement_test(06_windowed_cutoff_0.3 1 0.0001 06_additive_blending --falloff windowed --cutoff 0.3)
  course_forward_agreement_test(07_windowed_city 1 0.0001
    07_face_culling --falloff windowed --scene assets/scenes/city.scene)
  # The scene file chooses it: overlap.scene's twelve lights with `falloff windowed`. Summed in
  # RGBA32F (chapter 06) it matches forward to 1/255; in chapter 07's RGBA16F, half-float rounding
  # of sums near 1 adds a level, as on the hard overlap scene (tests/chapters/chapters_04_07.cmake):
  # measured max 2/255 on 0.30 % of pixels; bound 2, and no 3s.
  course_agreement_test(06_windowed_overlap_scene_rgba32f 1 0.0001
    06_additive_blending --scene ${S}/overlap_windowed.scene --cutoff 0.3 --accum rgba32f
    VS 00_forward --scene ${S}/overlap_windowed.scene --cutoff 0.3)
  course_forward_agreement_test(07_windowed_overlap_scene 2 0
    07_face_culling --scene ${S}/overlap_windowed.scene --cutoff 0.3)
  # It is a different model: at cut-off 0.3 the hard falloff's discs show, the windowed one's do not.
  chapters_04_07_expect_bug(07_windowed_differs_from_hard
    07_face_culling --cutoff 0.3 VS 07_face_culling --cutoff 0.3 --falloff windowed)
  # The docs' pictures (docs/05_attenuation_radius.md).
  course_golden_test(07_face_culling_cutoff_0.3_hard 07_face_culling 1 0.0001 --cutoff 0.3)
  course_golden_test(07_face_culling_cutoff_0.3_windowed 07_face_culling 1 0.0001 --cutoff 0.3 --falloff windowed)
endif()
