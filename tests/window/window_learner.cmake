# The learner's window (camera, lights, overlay, compare, leaks), driven by --script files under its
# own Xvfb with twm: tests/window/run_window_learner.sh says what each part checks. Skips (77) without
# Xvfb, twm or a GL context. The compare mode is checked in every deferred chapter with a lighting
# pass; the rest in chapter 07.
set(COURSE_LEARNER_CHAPTERS)
foreach(chapter 03_fullscreen_phong 04_light_volumes 05_attenuation_radius 06_additive_blending 08_stencil_volumes
                09_spot_lights 10_tiled_deferred 11_clustered 12_transparency 13_msaa 15_light_prepass)
  if(TARGET ${chapter})
    list(APPEND COURSE_LEARNER_CHAPTERS $<TARGET_FILE:${chapter}>)
  endif()
endforeach()
if(TARGET 07_face_culling)
  add_test(NAME window.learner
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/window/run_window_learner.sh $<TARGET_FILE:imgdiff>
            $<TARGET_FILE:window_check> ${CMAKE_BINARY_DIR}/test-out $<TARGET_FILE:07_face_culling>
            ${COURSE_LEARNER_CHAPTERS}
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(window.learner PROPERTIES LABELS window SKIP_RETURN_CODE 77 RUN_SERIAL TRUE
    FAIL_REGULAR_EXPRESSION "still alive at exit;FAIL")
endif()
