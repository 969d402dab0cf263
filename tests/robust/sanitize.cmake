# Sanitizer tests (label sanitize), only in a tree configured with COURSE_SANITIZE=ON (preset asan):
# one headless frame of every chapter on both headless back ends, under AddressSanitizer,
# LeakSanitizer and UndefinedBehaviorSanitizer. The unit tests of that tree run sanitized too.
# Mesa's own allocations are suppressed by tests/robust/lsan.supp; nothing of the course is.
if(COURSE_SANITIZE)
  set(COURSE_SANITIZE_ENV
    "ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1"
    "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/robust/lsan.supp:print_suppressions=0"
    "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
  foreach(chapter ${COURSE_CHAPTERS})
    foreach(backend egl osmesa)
      add_test(NAME sanitize.${chapter}.${backend}
        COMMAND $<TARGET_FILE:${chapter}> --headless=${backend} --size 160x120 --frames 1 --gl-debug
        WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
      set_tests_properties(sanitize.${chapter}.${backend} PROPERTIES LABELS sanitize SKIP_RETURN_CODE 77
        ENVIRONMENT "${COURSE_SANITIZE_ENV}"
        # A sanitizer report must fail the test even if the process somehow exits 0.
        FAIL_REGULAR_EXPRESSION "ERROR: (Address|Leak)Sanitizer|runtime error:|still alive at exit")
    endforeach()
  endforeach()
endif()

# The GL robustness tests run sanitized too: resizes and the error paths (a broken shader, a model
# Assimp rejects, a failed screenshot) are where memory is most easily lost.
if(COURSE_SANITIZE)
  foreach(name robust.gl_error robust.resize_leaks robust.inputs robust.options)
    if(TEST ${name})
      set_tests_properties(${name} PROPERTIES LABELS "robust;sanitize" ENVIRONMENT "${COURSE_SANITIZE_ENV}")
    endif()
  endforeach()
  # The bad-model corpus under the sanitizers: no report may pass (scene_check exits 2 either way).
  foreach(name bad.models_course bad.models_assimp)
    if(TEST ${name})
      set_tests_properties(${name} PROPERTIES ENVIRONMENT "${COURSE_SANITIZE_ENV}"
        FAIL_REGULAR_EXPRESSION "ERROR: (Address|Leak)Sanitizer|runtime error:")
    endif()
  endforeach()
endif()
