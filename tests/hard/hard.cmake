# Hard cases (label hard): numerical stability at the edges, docs/hard-cases.md explains each one.
# Programs in tests/hard/ make their own headless context and exit 77 when none can be made.

set(HARD_DIR ${CMAKE_SOURCE_DIR}/tests/hard)

function(course_hard_program name)
  add_executable(${name} ${HARD_DIR}/${name}.c ${HARD_DIR}/hard_util.c)
  target_link_libraries(${name} PRIVATE common)
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  add_test(NAME hard.${name} COMMAND ${name} ${ARGN} WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(hard.${name} PROPERTIES LABELS hard SKIP_RETURN_CODE 77)
endfunction()

# 5. position from depth: d24 / d32f / reversed-Z d32f at near 0.01, far 10,000
course_hard_program(hard_depth)

# 1, 7, 8, 9, 11, 13: the renderers in-process (forward, chapter 03's full-screen pass, chapter 07's
# light volumes), reading linear light and the RGBA16F accumulation buffer directly.
add_executable(hard_shading ${HARD_DIR}/hard_shading.c ${HARD_DIR}/hard_util.c)
target_link_libraries(hard_shading PRIVATE chapters)
set_target_properties(hard_shading PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
set(HARD_SCENES ${CMAKE_SOURCE_DIR}/tests/scenes)
foreach(case
    "shade" "grazing" "culled"
    "overlap@${HARD_SCENES}/hard_overlap200.scene"
    "hdr@${HARD_SCENES}/hard_hdr1e6.scene@${HARD_SCENES}/hard_hdr4096.scene"
    "degenerate@${HARD_SCENES}/hard_degenerate.scene"
    "counts@${CMAKE_SOURCE_DIR}/assets/scenes/default.scene")
  string(REPLACE "@" ";" args "${case}")
  list(GET args 0 name)
  add_test(NAME hard.${name} COMMAND hard_shading ${args} WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(hard.${name} PROPERTIES LABELS hard SKIP_RETURN_CODE 77)
endforeach()
# The chapter binaries themselves: chapter 07 (light volumes) against chapter 00 (forward).
if(TARGET 07_face_culling AND TARGET 00_forward)
  set(HARD_07 07_face_culling)
  # 1. a culled light and a constant-attenuation (full-screen) light, and the exact cut-off 0
  course_forward_agreement_test(hard_culled 1 0.0001 ${HARD_07} --scene tests/scenes/hard_culled.scene)
  course_forward_agreement_test(hard_cutoff0 1 0.0001 ${HARD_07} --cutoff 0)
  add_test(NAME hard.bench_culled COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/hard/run_hard_bench.sh
           $<TARGET_FILE:${HARD_07}> ${CMAKE_SOURCE_DIR}/tests/scenes/hard_culled.scene)
  set_tests_properties(hard.bench_culled PROPERTIES LABELS hard SKIP_RETURN_CODE 77)
  # 3 (camera inside a volume) and 4 (volumes across the far and near planes) are
  # agree.07_vs_forward_inside_volume / _far_plane / _near_plane in tests/chapters/chapters_04_07.cmake.
  # 8, 9 through the binaries as well (the in-process tests read the float buffers). The 200-light
  # overlap is compared in-process only: its pictures differ by a few levels (case 7 in the doc).
  foreach(scene hard_hdr1e6 hard_degenerate)
    course_forward_agreement_test(${scene} 1 0.0001 ${HARD_07} --scene tests/scenes/${scene}.scene)
  endforeach()
  # 12. extreme sizes
  add_test(NAME hard.sizes COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/hard/run_hard_sizes.sh $<TARGET_FILE:imgdiff>
           ${COURSE_TEST_OUT} $<TARGET_FILE:${HARD_07}> ${CMAKE_SOURCE_DIR}/assets/scenes/default.scene)
  set_tests_properties(hard.sizes PROPERTIES LABELS hard SKIP_RETURN_CODE 77)
endif()

# Chapter 08 (stencil light volumes): 3 (camera inside a volume) and 4 (the far and near planes) are
# agree.08_vs_forward_inside_volume / _far_plane / _near_plane / _near_plane_alone in
# tests/chapters/chapter_08.cmake, with the bug each choice prevents (agree.08_depth_pass_inside_vanishes,
# _depth_pass_near_plane, _no_depth_clamp_far_plane); 1, 8 and 9 there too (_culled, _cutoff0,
# _hdr1e6, _degenerate). 12. extreme sizes: a stencil and a depth copy at 16384x8 and 1x1.
if(TARGET 08_stencil_volumes)
  add_test(NAME hard.sizes_08 COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/hard/run_hard_sizes.sh $<TARGET_FILE:imgdiff>
           ${COURSE_TEST_OUT}/hard_sizes_08 $<TARGET_FILE:08_stencil_volumes>
           ${CMAKE_SOURCE_DIR}/assets/scenes/default.scene)
  set_tests_properties(hard.sizes_08 PROPERTIES LABELS hard SKIP_RETURN_CODE 77)
endif()

# 14. Spot lights (chapter 09's cone volumes): unit.test_cone_mesh and the camera inside a cone, apexes
# behind the near plane, cones across the far plane, each against forward
# (agree.09_vs_forward_spot_inside / _spot_near_plane / _spot_far_plane), are in tests/chapters/chapter_09.cmake.
