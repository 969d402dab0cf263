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

  # Every chapter with no light at all (lists, volumes, tiles and clusters of nothing).
  foreach(chapter ${COURSE_CHAPTERS})
    if(NOT chapter MATCHES "^1[4-9]_") # the shadowed ones get it below, with shadows asked for
      add_test(NAME sanitize.${chapter}.no_light
        COMMAND $<TARGET_FILE:${chapter}> --headless --size 160x120 --frames 1 --gl-debug --lights 0
        WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
      set_tests_properties(sanitize.${chapter}.no_light PROPERTIES LABELS sanitize SKIP_RETURN_CODE 77
        ENVIRONMENT "${COURSE_SANITIZE_ENV}" TIMEOUT 120
        FAIL_REGULAR_EXPRESSION "ERROR: (Address|Leak)Sanitizer|runtime error:|still alive at exit")
    endif()
  endforeach()

  # The shadowed chapters (14 and every one built on it) with no light shadowed: an empty shadow
  # plan has no array to sort, and UBSan stops on qsort(NULL, 0, ...). Three ways to get there:
  # --shadows 0, no light at all, and a scene whose lights are all `shadow off`. Chapters 15-19
  # shadow nothing by default (--shadows 0 turns the atlas off there), so the last two ask for it.
  foreach(chapter 14_shadows 15_light_prepass 16_visibility_buffer 17_ssao 18_pbr_materials 19_image_based_light)
    set(on --shadows 1)
    if(chapter STREQUAL 14_shadows)
      set(on "") # every light by default
    endif()
    foreach(case "no_shadow|--shadows@0" "no_light|--lights@0"
                 "all_off|--scene@${CMAKE_SOURCE_DIR}/tests/scenes/shadow_all_off.scene")
      string(REPLACE "|" ";" parts "${case}")
      list(GET parts 0 name)
      list(GET parts 1 args)
      string(REPLACE "@" ";" args "${args}")
      if(NOT name STREQUAL no_shadow)
        list(APPEND args ${on})
      endif()
      add_test(NAME sanitize.${chapter}.${name}
        COMMAND $<TARGET_FILE:${chapter}> --headless --size 160x120 --frames 1 --gl-debug ${args}
        WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
      set_tests_properties(sanitize.${chapter}.${name} PROPERTIES LABELS sanitize SKIP_RETURN_CODE 77
        ENVIRONMENT "${COURSE_SANITIZE_ENV}" TIMEOUT 120
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
