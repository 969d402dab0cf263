# Platform and command-line tests: every shader validates, every binary answers --help and
# rejects bad input with exit 2 and one line, and a chapter runs in a real window under Xvfb.

add_test(NAME shaders.glslang COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/robust/run_glslang.sh ${CMAKE_SOURCE_DIR}/shaders)
set_tests_properties(shaders.glslang PROPERTIES LABELS unit SKIP_RETURN_CODE 77)

foreach(chapter ${COURSE_CHAPTERS})
  add_test(NAME cli.${chapter} COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/robust/run_cli.sh
           $<TARGET_FILE:${chapter}> ${CMAKE_SOURCE_DIR}
           WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(cli.${chapter} PROPERTIES LABELS unit SKIP_RETURN_CODE 77)
endforeach()

# The window path: GLFW under Xvfb, a few frames, and the last one must equal the headless golden.
find_program(XVFB_RUN xvfb-run)
if(XVFB_RUN)
  foreach(chapter ${COURSE_CHAPTERS})
    add_test(NAME window.${chapter}
      COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/golden/run_golden.sh $<TARGET_FILE:imgdiff> ${COURSE_TEST_OUT}
              window.${chapter} ${CMAKE_SOURCE_DIR}/tests/golden/${chapter}.png 1 0.0001
              -- ${XVFB_RUN} -a -s "-screen 0 1280x1024x24"
                 $<TARGET_FILE:${chapter}> --size ${COURSE_GOLDEN_SIZE} --frames 3 --paused --gl-debug
                 --scene ${CMAKE_SOURCE_DIR}/assets/scenes/default.scene
      WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
    set_tests_properties(window.${chapter} PROPERTIES LABELS window SKIP_RETURN_CODE 77 RUN_SERIAL TRUE)
  endforeach()
endif()

# The window's frame time is a true frame time, checked against other clocks of the same process
# on the same frames (never against a run made at another moment, which a loaded machine makes
# disagree): with --bench, each title figure within [0.5 x min_ms, max_ms + 0.01] of the bench
# line and the title's passes summing to its frame figure; without --bench (whose pixel count
# makes every frame wait for its work), the titles at least 0.2 of the frames' period.
# tests/window/run_window_timing.sh gives each tolerance's reason. RUN_SERIAL is kept as for the other
# window tests; the verdict does not need it.
if(XVFB_RUN AND TARGET 07_face_culling)
  add_test(NAME window.timing_matches_bench
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/window/run_window_timing.sh ${XVFB_RUN} $<TARGET_FILE:07_face_culling>
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(window.timing_matches_bench PROPERTIES LABELS window SKIP_RETURN_CODE 77 RUN_SERIAL TRUE)
endif()

# Both frame clocks run here (the GPU query path is forced; tests/window/run_frame_clock.sh).
if(TARGET 07_face_culling)
  add_test(NAME robust.frame_clocks COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/window/run_frame_clock.sh
           $<TARGET_FILE:07_face_culling> WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(robust.frame_clocks PROPERTIES LABELS robust SKIP_RETURN_CODE 77)
endif()

# Compare mode times forward as its own pass on the same clock, and the chapter's figure leaves it
# out, in --bench, the title and the overlay alike (tests/window/run_compare_timing.sh). Chapter 07
# (the runner's forward), 11 (its own clustered frame) and 13 (its own forward MSAA draw_forward).
foreach(chapter 07_face_culling 11_clustered 13_msaa)
  if(TARGET ${chapter})
    add_test(NAME compare.timing.${chapter}
      COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/window/run_compare_timing.sh $<TARGET_FILE:${chapter}>
      WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
    set_tests_properties(compare.timing.${chapter} PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
  endif()
endforeach()

# The overlay as a learner reads it: wrapped inside the picture, replaced by F1's list while that
# shows, naming what each chapter counts (tests/window/run_overlay_fit.sh).
if(TARGET 07_face_culling AND TARGET 11_clustered)
  add_test(NAME overlay.fit
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/window/run_overlay_fit.sh $<TARGET_FILE:imgdiff>
            $<TARGET_FILE:07_face_culling> $<TARGET_FILE:11_clustered>
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(overlay.fit PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
endif()

# F1's key list, the longest of all chapters, is shown whole: no fixed buffer cuts it, and the picture
# holds it at the default size (tests/window/run_key_list.sh).
set(COURSE_KEY_LIST_CHAPTERS)
foreach(chapter ${COURSE_CHAPTERS})
  list(APPEND COURSE_KEY_LIST_CHAPTERS $<TARGET_FILE:${chapter}>)
endforeach()
add_test(NAME overlay.key_list
  COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/window/run_key_list.sh ${COURSE_KEY_LIST_CHAPTERS}
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(overlay.key_list PROPERTIES LABELS golden SKIP_RETURN_CODE 77)

# Compare mode reports forward's time honestly under load: never 0 ms for a frame that drew forward,
# "not timed yet" for one whose figures predate M (tests/window/run_compare_honest.sh, a busy loop
# beside it). Chapter 07 (the runner's forward, on the default scene) and 18 (its own forward, at the
# exposure, on its PBR teapots).
foreach(chapter 07_face_culling 18_pbr_materials)
  if(TARGET ${chapter})
    add_test(NAME compare.honest.${chapter}
      COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/window/run_compare_honest.sh $<TARGET_FILE:${chapter}>
      WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
    set_tests_properties(compare.honest.${chapter} PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
  endif()
endforeach()
