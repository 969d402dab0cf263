# Chapter 17's ambient occlusion against an exact reference (label hard): tests/ssao/test_ssao_reference.c
# casts, in double precision, 64 x 64 cosine-weighted rays per pixel within the radius from the surface
# behind each pixel of tests/scenes/ssao_boxes.scene at 160x120 (its own noise measured and held under
# 1/255), and compares with the chapter's --view ao / ao-blurred. The first configuration (the
# defaults: 16 directions, blur 2) is the bound checked; the others are printed for the page's table.
# Measured on llvmpipe: mean 0.0112, 3.07 % of pixels beyond 0.1; checked: 0.013 and 3.5 % (docs/17_ssao.md).
# The hard cases, each bounded by its measured share beyond 0.1, rounded up: silhouettes 1.81 % (2 %),
# the border 2.01 % (2.5 %), near the thin post 18.1 % (20 %: behind it the depth buffer says solid),
# far floor 0 % (0.1 %: the plane test keeps a grazing floor open).: a depth buffer sees only the
# nearest surface, so behind a silhouette and under the thin post SSAO guesses, and 16 directions
# leave noise the 4 x 4 blur only averages.

if(TARGET 17_ssao)
  add_executable(test_ssao_reference ${CMAKE_SOURCE_DIR}/tests/ssao/test_ssao_reference.c
                 ${CMAKE_SOURCE_DIR}/tests/hard/hard_util.c)
  target_link_libraries(test_ssao_reference PRIVATE chapters reference_readback)
  target_include_directories(test_ssao_reference PRIVATE ${CMAKE_SOURCE_DIR}/tests/hard)
  set_target_properties(test_ssao_reference PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  add_test(NAME hard.ssao_reference
    COMMAND test_ssao_reference ${CMAKE_SOURCE_DIR}/tests/scenes/ssao_boxes.scene 0.5 0.013 0.1 0.035 0.02 0.025 0.2 0.001
            16 2  16 0  4 0  4 2  64 0  64 2  32 4
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(hard.ssao_reference PROPERTIES LABELS hard SKIP_RETURN_CODE 77)
endif()

# The occlusion's keys (T / Y, J / L, B / N) draw, byte for byte, what the matching option draws from
# the start, in chapter 17 and in chapter 19 (which shares them, common/render/ssao.c: ssao_key).
foreach(chapter 17_ssao 19_image_based_light)
  if(TARGET ${chapter})
    add_test(NAME window.${chapter}_ssao_keys
      COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/ssao/run_ssao_keys.sh $<TARGET_FILE:imgdiff> ${COURSE_TEST_OUT}
              $<TARGET_FILE:${chapter}> --scene ${CMAKE_SOURCE_DIR}/tests/scenes/ssao_boxes.scene
      WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
    set_tests_properties(window.${chapter}_ssao_keys PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
  endif()
endforeach()
