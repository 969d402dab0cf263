# Golden and agreement tests (label golden): headless renders at a small size.
#
#   course_golden_test(NAME BINARY TOLERANCE MAX_FRACTION [ARGS...])
#       BINARY's picture must match tests/golden/NAME.png. `update-goldens` rewrites these.
#   course_agreement_test(NAME TOLERANCE MAX_FRACTION BINARY_A ARGS_A... VS BINARY_B ARGS_B...)
#       two renderings of the same frame must agree.
#   course_forward_agreement_test(NAME TOLERANCE MAX_FRACTION BINARY [ARGS...])
#       BINARY with ARGS must agree with 00_forward given the same ARGS.
#
# Every render runs with --gl-debug, so a GL error fails the test.
# Tolerances: llvmpipe is deterministic (byte-identical PNGs across runs and thread counts), so a
# golden must match to 1/255 on 99.99 % of pixels; the slack only absorbs a Mesa update that
# rounds a handful of pixels the other way.

set(COURSE_GOLDEN_SIZE 320x240)

# Every golden and agreement test is recorded here (its run_golden.sh / run_agreement.sh arguments),
# and tests/softpipe/softpipe.cmake registers it a second time as softpipe.TEST, on Mesa's softpipe,
# once every module has added its tests (so that it can copy their properties).
function(course_softpipe_record test)
  set_property(GLOBAL APPEND PROPERTY COURSE_SOFTPIPE_TESTS ${test})
  set_property(GLOBAL PROPERTY COURSE_SOFTPIPE_ARGS_${test} ${ARGN})
endfunction()

set(COURSE_TEST_OUT ${CMAKE_BINARY_DIR}/test-out)
# The default scene by name: chapters 09 and 12 open on their lesson's scene (spots, glass) without
# --scene, and every test says which scene it draws (a test's own --scene comes later and wins).
set(COURSE_RENDER_ARGS --headless --size ${COURSE_GOLDEN_SIZE} --frames 1 --gl-debug
    --scene ${CMAKE_SOURCE_DIR}/assets/scenes/default.scene)

function(course_golden_test name binary tolerance fraction)
  add_test(NAME golden.${name}
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/golden/run_golden.sh $<TARGET_FILE:imgdiff> ${COURSE_TEST_OUT}
            ${name} ${CMAKE_SOURCE_DIR}/tests/golden/${name}.png ${tolerance} ${fraction}
            -- $<TARGET_FILE:${binary}> ${COURSE_RENDER_ARGS} ${ARGN}
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(golden.${name} PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
  course_softpipe_record(golden.${name} golden ${name} ${CMAKE_SOURCE_DIR}/tests/golden/${name}.png
    ${tolerance} ${fraction} -- $<TARGET_FILE:${binary}> ${COURSE_RENDER_ARGS} ${ARGN})
  # One list entry per case: fields joined by '|', arguments by '@' (';' would split the entry).
  string(REPLACE ";" "@" args "${COURSE_RENDER_ARGS};${ARGN}")
  set_property(GLOBAL APPEND PROPERTY COURSE_GOLDEN_CASES "${name}|$<TARGET_FILE:${binary}>|${args}")
endfunction()

function(course_agreement_test name tolerance fraction)
  set(cmd_a "")
  set(cmd_b "")
  set(side a)
  foreach(arg ${ARGN})
    if(arg STREQUAL "VS")
      set(side b)
    elseif(side STREQUAL "a")
      list(APPEND cmd_a ${arg})
    else()
      list(APPEND cmd_b ${arg})
    endif()
  endforeach()
  list(POP_FRONT cmd_a bin_a)
  list(POP_FRONT cmd_b bin_b)
  add_test(NAME agree.${name}
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/golden/run_agreement.sh $<TARGET_FILE:imgdiff> ${COURSE_TEST_OUT}
            ${name} ${tolerance} ${fraction}
            -- $<TARGET_FILE:${bin_a}> ${COURSE_RENDER_ARGS} ${cmd_a}
            -- $<TARGET_FILE:${bin_b}> ${COURSE_RENDER_ARGS} ${cmd_b}
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(agree.${name} PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
  course_softpipe_record(agree.${name} agreement ${name} ${tolerance} ${fraction}
    -- $<TARGET_FILE:${bin_a}> ${COURSE_RENDER_ARGS} ${cmd_a}
    -- $<TARGET_FILE:${bin_b}> ${COURSE_RENDER_ARGS} ${cmd_b})
endfunction()

function(course_forward_agreement_test name tolerance fraction binary)
  course_agreement_test(${name} ${tolerance} ${fraction} ${binary} ${ARGN} VS 00_forward ${ARGN})
endfunction()

# Every chapter's own picture on the default scene.
foreach(chapter ${COURSE_CHAPTERS})
  course_golden_test(${chapter} ${chapter} 1 0.0001)
endforeach()

# Chapter 00: the optimisations change the speed, never the picture.
foreach(variant forward-naive forward-prepass forward-lists)
  course_agreement_test(00_${variant} 1 0.0001
    00_forward --renderer forward VS 00_forward --renderer ${variant})
endforeach()
course_agreement_test(00_osmesa_vs_egl 1 0.0001
  00_forward VS 00_forward --headless=osmesa)

# A case written "NAME|ARG@ARG@...": its name into name_var and its arguments, as a list, into
# args_var (an argument with spaces, such as --camera's, stays one argument).
macro(course_case case name_var args_var)
  string(REPLACE "|" ";" _course_case_parts "${case}")
  list(GET _course_case_parts 0 ${name_var})
  list(GET _course_case_parts 1 ${args_var})
  string(REPLACE "@" ";" ${args_var} "${${args_var}}")
endmacro()

# The heat map read back into counts and compared with the count the run claims
# (tests/golden/run_overdraw_count.sh: CLAIM is lit-run, loop, ...); ARGN: the program and its arguments.
function(course_overdraw_count_test name claim)
  add_test(NAME overdraw.${name}
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/golden/run_overdraw_count.sh $<TARGET_FILE:heat_count>
            ${COURSE_TEST_OUT}/overdraw_${name}.png ${claim} -- ${ARGN}
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(overdraw.${name} PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
endfunction()

# A chapter's choice between compute shaders and its GL 3.3 path (--OPTION compute|cpu, the key L):
# chapters.NAME_no_compute, where compute is asked for on a context without it (one clear line,
# exit 1; the default falls back; simulated with COURSE_NO_COMPUTE=1), and chapters.NAME_key, where
# L switches the path at run time with the same picture (WHAT: the log's name for the lists).
function(course_compute_path_tests name binary option what)
  add_test(NAME chapters.${name}_no_compute
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/golden/run_no_compute.sh $<TARGET_FILE:${binary}>
            ${COURSE_TEST_OUT}/${name}_no_compute ${option}
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  add_test(NAME chapters.${name}_key
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/golden/run_compute_key.sh $<TARGET_FILE:${binary}>
            ${COURSE_TEST_OUT}/${name}_key ${option} "${what}"
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.${name}_no_compute chapters.${name}_key PROPERTIES LABELS golden
    SKIP_RETURN_CODE 77)
endfunction()
