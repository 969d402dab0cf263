# Chapter 19's probes against exact references (label hard): tests/ibl/test_ibl_reference.c reads back
# the default scene's first probe (its capture, prefiltered chain, harmonics and the split-sum table)
# and compares, in double precision: the split sum with a Monte Carlo integral of the full GGX BRDF
# per roughness, the harmonics with a cosine integral of every texel; then the hard cases roughness 0,
# a seam, and a probe inside a box (tests/scenes/ibl_inside.scene). Bounds per roughness 0, 0.25,
# 0.5, 0.75, 1: the mean relative error measured on llvmpipe (0.0004, 0.079, 0.177, 0.156, 0.031 at
# the chapter's 256 samples), with about a third more for another driver's rounding and sampling
# (the table is printed; docs/19_image_based_light.md).
if(TARGET 19_image_based_light)
  add_executable(test_ibl_reference ${CMAKE_SOURCE_DIR}/tests/ibl/test_ibl_reference.c
                 ${CMAKE_SOURCE_DIR}/tests/hard/hard_util.c)
  target_link_libraries(test_ibl_reference PRIVATE chapters reference_readback)
  target_include_directories(test_ibl_reference PRIVATE ${CMAKE_SOURCE_DIR}/tests/hard)
  set_target_properties(test_ibl_reference PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  add_test(NAME hard.ibl_reference
    COMMAND test_ibl_reference ${CMAKE_SOURCE_DIR}/assets/scenes/default.scene
            ${CMAKE_SOURCE_DIR}/tests/scenes/ibl_inside.scene 0.001 0.11 0.24 0.21 0.05
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(hard.ibl_reference PROPERTIES LABELS hard SKIP_RETURN_CODE 77)
endif()
