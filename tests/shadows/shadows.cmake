# Chapter 14's shadows against exact shadow rays (label hard): tests/shadows/test_shadow_reference.c
# traces, in double precision, the surface behind each pixel and a ray from it to the light, and
# compares with the chapter's --view visibility. The first configuration of each case is the bound
# checked (docs/14_shadows.md gives the reason for each); the others are printed for the page's table.
# Hard cases on docs/hard-cases.md (14.1 to 14.8) say which test covers each.

if(TARGET 14_shadows)
  add_executable(test_shadow_reference ${CMAKE_SOURCE_DIR}/tests/shadows/test_shadow_reference.c
                 ${CMAKE_SOURCE_DIR}/tests/hard/hard_util.c)
  target_link_libraries(test_shadow_reference PRIVATE chapters reference)
  target_include_directories(test_shadow_reference PRIVATE ${CMAKE_SOURCE_DIR}/tests/hard)
  set_target_properties(test_shadow_reference PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  set(SS ${CMAKE_SOURCE_DIR}/tests/scenes)
  # The default atlas, PCF and bias: at most 0.5 % of lit pixels wrong (the issue's target), then
  # the sweep: the atlas (the light's tile size follows it), PCF 1/3/5, no bias, either bias alone,
  # the normal offset doubled and at the defaults before 2026-12-02 (PCF 3, 1.5 texels), both doubled.
  set(SWEEP 4096 1 0.25 2  512 1 0.25 2  1024 1 0.25 2  2048 1 0.25 2  4096 3 0.25 2  4096 5 0.25 2
            4096 1 0 0  4096 1 0 2  4096 1 0.25 0  4096 1 0.5 2  4096 3 1.5 2  4096 1 0.5 4)
  foreach(case one_light spot contact grazing inside)
    add_test(NAME hard.shadow_reference_${case}
      COMMAND test_shadow_reference ${SS}/shadow_${case}.scene 0.005 ${SWEEP}
      WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
    set_tests_properties(hard.shadow_reference_${case} PROPERTIES LABELS hard SKIP_RETURN_CODE 77)
  endforeach()
  # The teapots' 80 lights, 8 of them measured (every 10th), each alone through --view-light, at the
  # default atlas, PCF and bias (about 15 s), then at the defaults before 2026-12-02 (PCF 3, 1.5 texels)
  # for the page. Measured on 2026-12-02: 0.4221 % of 54,011 lit pixels wrong (192 leaks, 36 acne),
  # against 0.8184 % at the old defaults. The bound is the issue's target, 0.5 %: the measurement keeps
  # a sixth of it as margin.
  add_test(NAME hard.shadow_reference_teapots
    COMMAND test_shadow_reference ${CMAKE_SOURCE_DIR}/assets/scenes/teapots.scene 0.005 4096 1 0.25 2 4096 3 1.5 2
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(hard.shadow_reference_teapots PROPERTIES LABELS hard SKIP_RETURN_CODE 77)
endif()

# Chapters 15 to 19 take chapter 14's atlas with --shadows N, off by default (their own pictures,
# goldens and agreements are unchanged; their shadowed agreements are in tests/chapters/chapter_NN.cmake):
# --help names the options and the key (18's is N: its K moves the lights), and the key, driven by a
# --script, turns them off to the chapter's picture without --shadows, byte for byte, and says how to
# start with them when there are none.
if(TARGET 14_shadows)
  set(A ${CMAKE_SOURCE_DIR}/assets/scenes)
  foreach(case "15_light_prepass|K|--scene@${A}/teapots.scene" "16_visibility_buffer|K|--scene@${A}/teapots.scene"
               "17_ssao|K|--scene@${A}/teapots.scene" "18_pbr_materials|N|--scene@${A}/pbr_teapots.scene"
               "19_image_based_light|K|--scene@${A}/teapots_probes.scene")
    string(REPLACE "|" ";" parts "${case}")
    list(GET parts 0 chapter)
    list(GET parts 1 key)
    list(GET parts 2 args)
    string(REPLACE "@" ";" args "${args}")
    if(NOT TARGET ${chapter})
      continue()
    endif()
    add_test(NAME chapters.${chapter}_help_shadows COMMAND ${chapter} --help WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
    set_tests_properties(chapters.${chapter}_help_shadows PROPERTIES LABELS golden
      PASS_REGULAR_EXPRESSION "--shadows N +chapter 14's shadows for the N most important.*--pcf N +with --shadows.*--shadow-atlas SIZE +with --shadows.*\n  ${key} +shadows on / off")
    add_test(NAME window.${chapter}_shadow_keys
      COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/shadows/run_later_shadow_keys.sh $<TARGET_FILE:imgdiff>
              ${COURSE_TEST_OUT} $<TARGET_FILE:${chapter}> ${key} ${args}
      WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
    set_tests_properties(window.${chapter}_shadow_keys PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
  endforeach()
endif()
