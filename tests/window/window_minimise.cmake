# A window minimised and restored (docs/hard-cases.md, case 12): tests/window/run_minimise.sh runs its own
# Xvfb with the twm window manager (iconifying needs one), minimises and restores each window 3
# times with --minimise-cycle, fails if a frame was drawn while minimised or a GL object leaked, and
# compares the last frame with the golden. Skips (77) without Xvfb or twm; without a window manager
# a run must skip too, never pass, and the script checks that first.
set(COURSE_MINIMISE_CHAPTERS)
foreach(chapter 00_forward 07_face_culling)
  if(TARGET ${chapter})
    list(APPEND COURSE_MINIMISE_CHAPTERS $<TARGET_FILE:${chapter}>)
  endif()
endforeach()
if(COURSE_MINIMISE_CHAPTERS)
  add_test(NAME window.minimise
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/window/run_minimise.sh $<TARGET_FILE:imgdiff>
            ${CMAKE_BINARY_DIR}/test-out ${CMAKE_SOURCE_DIR}/tests/golden ${COURSE_MINIMISE_CHAPTERS}
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(window.minimise PROPERTIES LABELS window SKIP_RETURN_CODE 77 RUN_SERIAL TRUE
    FAIL_REGULAR_EXPRESSION "still alive at exit")
endif()
