# Robustness tests (docs/testing.md): GL errors fail, resizes leak nothing, every bad input gets a
# clear message and the right exit code, and a failed run loses no earlier output.
#
#   robust.gl_error            tests/gl/test_gl_error.c: a deliberate GL error is counted by the
#                              KHR_debug callback and reported by gl_check
#   robust.resize_leaks        tests/gl/test_resize_leaks.c: 200 resizes of target + G-buffer + light
#                              volumes, live GL objects unchanged, replaced objects deleted
#   robust.draw_count          tests/gl/test_draw_count.c: the storage table's byte counter on draws
#                              whose bytes are known (formats, masks, blending, discard, nesting)
#   robust.resize_cycle.NN     every chapter, headless, --resize-cycle 200 (app.c fails the run if
#                              the live GL objects grew), last frame equal to a plain run's
#   window.resize_cycle.NN     the window under Xvfb resized 200 times (glfwSetWindowSize), last
#                              frame equal to a headless run's
#   robust.options             tests/robust/run_options.sh: each chapter's bad option values exit 2
#                              before a context; --scene/--script found from any folder
#   robust.inputs              tests/robust/run_robust.sh: render-time model errors (tests/bad/*.scene
#                              marked "# expect-at: render"), broken and missing shaders, no GL at
#                              all, outputs kept when a run fails
set(COURSE_GL_TESTS test_gl_error test_resize_leaks test_draw_count)
foreach(name ${COURSE_GL_TESTS})
  add_executable(${name} ${CMAKE_CURRENT_SOURCE_DIR}/gl/${name}.c)
  target_link_libraries(${name} PRIVATE common)
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
endforeach()
add_test(NAME robust.gl_error COMMAND test_gl_error)
add_test(NAME robust.resize_leaks COMMAND test_resize_leaks)
add_test(NAME robust.draw_count COMMAND test_draw_count)
set_tests_properties(robust.gl_error robust.resize_leaks robust.draw_count PROPERTIES LABELS robust
  SKIP_RETURN_CODE 77)

# The picture after 200 resizes and back must equal a plain run's (no golden needed: stale state
# after a resize, such as a viewport or an attachment left at an old size, shows up here).
set(COURSE_RESIZE_CYCLES 200)
foreach(chapter ${COURSE_CHAPTERS})
  add_test(NAME robust.resize_cycle.${chapter}
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/golden/run_agreement.sh $<TARGET_FILE:imgdiff>
            ${CMAKE_BINARY_DIR}/test-out resize_cycle.${chapter} 1 0.0001
            -- $<TARGET_FILE:${chapter}> --headless --size 128x96 --frames 1 --gl-debug
               --resize-cycle ${COURSE_RESIZE_CYCLES}
            -- $<TARGET_FILE:${chapter}> --headless --size 128x96 --frames 1 --gl-debug
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(robust.resize_cycle.${chapter} PROPERTIES LABELS robust SKIP_RETURN_CODE 77
    FAIL_REGULAR_EXPRESSION "still alive at exit")
endforeach()

find_program(XVFB_RUN xvfb-run)
if(XVFB_RUN)
  # One chapter per renderer family keeps the window tests short: forward, full-screen deferred,
  # light volumes. The headless tests above cover every chapter's resize callback.
  foreach(chapter 00_forward 03_fullscreen_phong 07_face_culling)
    if(TARGET ${chapter})
      add_test(NAME window.resize_cycle.${chapter}
        COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/golden/run_agreement.sh $<TARGET_FILE:imgdiff>
                ${CMAKE_BINARY_DIR}/test-out window.resize_cycle.${chapter} 1 0.0001
                -- ${XVFB_RUN} -a -s "-screen 0 1280x1024x24"
                   $<TARGET_FILE:${chapter}> --size 320x240 --frames 2 --paused --gl-debug
                   --resize-cycle ${COURSE_RESIZE_CYCLES}
                -- $<TARGET_FILE:${chapter}> --headless --size 320x240 --frames 1 --gl-debug
        WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
      set_tests_properties(window.resize_cycle.${chapter} PROPERTIES LABELS window SKIP_RETURN_CODE 77
        RUN_SERIAL TRUE)
    endif()
  endforeach()
endif()

if(TARGET 00_forward)
  add_test(NAME robust.inputs
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/robust/run_robust.sh $<TARGET_FILE:00_forward> ${CMAKE_SOURCE_DIR}
            $<TARGET_FILE:imgdiff>
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(robust.inputs PROPERTIES LABELS robust SKIP_RETURN_CODE 77)
endif()

# Every bad option value of every chapter exits 2 before any context (run_options.sh says how that is
# shown); input files found from any folder; the context's own limits in the same words.
if(TARGET 13_msaa)
  add_test(NAME robust.options
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/robust/run_options.sh ${CMAKE_BINARY_DIR}/bin ${CMAKE_SOURCE_DIR}
            $<$<BOOL:${COURSE_SANITIZE}>:sanitized>)
  set_tests_properties(robust.options PROPERTIES LABELS robust SKIP_RETURN_CODE 77)
endif()

# The binaries run from any folder, and an installed prefix works after being moved.
add_test(NAME robust.install COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/robust/run_install.sh ${CMAKE_BINARY_DIR})
set_tests_properties(robust.install PROPERTIES LABELS robust SKIP_RETURN_CODE 77)

# The tests' scripts a page tells a learner to run print their usage and refuse what they do not take
# (an option, a wrong count), and never delete a folder they did not make (tests/lib/args.sh).
add_test(NAME robust.test_scripts
  COMMAND ${BASH} -c "set -u; tmp=$(mktemp -d); trap 'rm -rf $tmp' EXIT; s=tests/chapters/run_clustered_work.sh; \
    bash $s --tile 16 2>$tmp/err; [ $? -eq 2 ] && grep -q \"unknown option '--tile'\" $tmp/err && grep -q '^run_clustered_work.sh BENCH' $tmp/err || { echo FAIL option; cat $tmp/err; exit 1; }; \
    bash $s --help 2>$tmp/err; [ $? -eq 2 ] && grep -q 'BENCH CHAPTER_11 OUT_DIR' $tmp/err || { echo FAIL help; exit 1; }; \
    bash $s a b 2>$tmp/err; [ $? -eq 2 ] && grep -q '2 argument(s) given, 3 expected' $tmp/err || { echo FAIL count; exit 1; }; \
    mkdir $tmp/mine && echo keep >$tmp/mine/notes.txt; \
    bash $s $<TARGET_FILE:bench> $<TARGET_FILE:11_clustered> $tmp/mine 2>$tmp/err; \
    [ $? -eq 2 ] && grep -q 'was not made by a course test' $tmp/err && [ -f $tmp/mine/notes.txt ] || { echo FAIL kept; exit 1; }; \
    echo 'ok: usage, refusals, and the learner folder kept'"
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(robust.test_scripts PROPERTIES LABELS robust)
