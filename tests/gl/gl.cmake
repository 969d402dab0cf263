# Programs built for the scene (common/gl/shader_features.h): tests/gl/test_scene_programs.c opens every
# chapter in every renderer on the default scene (Blinn-Phong, no images) and finds no material-image
# sampler in any program it built, and finds them on pbr_teapots (the check can fail).
if(TARGET chapters)
  add_executable(test_scene_programs ${CMAKE_SOURCE_DIR}/tests/gl/test_scene_programs.c
                 ${CMAKE_SOURCE_DIR}/tests/hard/hard_util.c)
  target_link_libraries(test_scene_programs PRIVATE chapters)
  target_include_directories(test_scene_programs PRIVATE ${CMAKE_SOURCE_DIR}/tests/hard)
  set_target_properties(test_scene_programs PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  add_test(NAME golden.scene_programs
    COMMAND test_scene_programs ${CMAKE_SOURCE_DIR}/assets/scenes/default.scene
            ${CMAKE_SOURCE_DIR}/assets/scenes/pbr_teapots.scene
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(golden.scene_programs PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
endif()
# Chapter 14 with no light shadowed, 17's --ssao off and 19's --ibl off compile their lighting programs
# without the feature, and with it on compile it in (tests/gl/run_feature_off_programs.sh).
if(TARGET 14_shadows AND TARGET 17_ssao AND TARGET 19_image_based_light)
  add_test(NAME golden.feature_off_programs
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/gl/run_feature_off_programs.sh $<TARGET_FILE:14_shadows>
            $<TARGET_FILE:17_ssao> $<TARGET_FILE:19_image_based_light>
            ${CMAKE_SOURCE_DIR}/assets/scenes/default.scene ${COURSE_TEST_OUT}
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(golden.feature_off_programs PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
endif()
