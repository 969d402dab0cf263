# The course's layout as checks: each chapter's lesson is greppable in that chapter first, and each
# page's "what changed" block is the real diff of the two chapter files (tests/lessons/doc_diffs.py).
add_test(NAME lessons.first_in_chapter COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/lessons/run_lessons.sh ${CMAKE_SOURCE_DIR})
find_program(SYSTEM_PYTHON3 python3 PATHS /usr/bin NO_DEFAULT_PATH)
add_test(NAME lessons.what_changed COMMAND ${SYSTEM_PYTHON3} ${CMAKE_SOURCE_DIR}/tests/lessons/doc_diffs.py --check ${CMAKE_SOURCE_DIR})
set_tests_properties(lessons.first_in_chapter lessons.what_changed PROPERTIES LABELS unit)
# ... and each chapter page's Keys paragraph names M and the chapter's own keys of the key table.
set_tests_properties(lessons.first_in_chapter PROPERTIES ENVIRONMENT "KEY_TABLE=$<TARGET_FILE:key_table>")
# Every measured figure a page shows is a verbatim copy of one dated run in docs/data/
# (scripts/update-docs.sh writes it; tests/lessons/doc_generated.py compares).
add_test(NAME lessons.generated_figures
  COMMAND ${SYSTEM_PYTHON3} ${CMAKE_SOURCE_DIR}/tests/lessons/doc_generated.py --check ${CMAKE_SOURCE_DIR})
set_tests_properties(lessons.generated_figures PROPERTIES LABELS unit)
# The README's key table is common/platform/keys.c's (tools/key_table prints it).
add_test(NAME lessons.key_table COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/lessons/run_key_table.sh
         $<TARGET_FILE:key_table> ${CMAKE_SOURCE_DIR}/README.md)
set_tests_properties(lessons.key_table PROPERTIES LABELS unit)
# common/ in layers: every include points down or sideways, no cycle (tests/lessons/check_layers.py), and the
# check refuses a tree that breaks each rule (tests/data/layers_bad: an upward include, the cycle it
# makes, a folder that is no layer).
add_test(NAME lessons.layers COMMAND ${SYSTEM_PYTHON3} ${CMAKE_SOURCE_DIR}/tests/lessons/check_layers.py ${CMAKE_SOURCE_DIR})
add_test(NAME lessons.layers_refused
  COMMAND ${BASH} -c "out=$(${SYSTEM_PYTHON3} tests/lessons/check_layers.py tests/data/layers_bad) && exit 1; \
    echo \"$out\"; grep -q 'higher layer app' <<<\"$out\" && grep -q 'include cycle' <<<\"$out\" && \
    grep -q 'not a layer folder' <<<\"$out\""
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(lessons.layers lessons.layers_refused PROPERTIES LABELS unit)
# Every command a page shows runs as written (tests/lessons/page_commands.py): one test per page, from
# a scratch folder laid out like the repository, headless; and the check refuses a page with each
# kind of broken command (tests/data/pages_bad/bad.md).
execute_process(COMMAND ${SYSTEM_PYTHON3} ${CMAKE_SOURCE_DIR}/tests/lessons/page_commands.py --list ${CMAKE_SOURCE_DIR}
                OUTPUT_VARIABLE COURSE_PAGES_WITH_COMMANDS OUTPUT_STRIP_TRAILING_WHITESPACE)
string(REPLACE "\n" ";" COURSE_PAGES_WITH_COMMANDS "${COURSE_PAGES_WITH_COMMANDS}")
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/README.md)
foreach(page ${COURSE_PAGES_WITH_COMMANDS})
  string(REGEX REPLACE "^docs/|\\.md$" "" name ${page})
  add_test(NAME pages.commands.${name}
    COMMAND ${SYSTEM_PYTHON3} ${CMAKE_SOURCE_DIR}/tests/lessons/page_commands.py --run ${CMAKE_SOURCE_DIR}
            ${CMAKE_BINARY_DIR} ${page})
  set_tests_properties(pages.commands.${name} PROPERTIES LABELS golden SKIP_RETURN_CODE 77 TIMEOUT 900)
endforeach()
add_test(NAME pages.commands_refused
  COMMAND ${BASH} -c "out=$(${SYSTEM_PYTHON3} tests/lessons/page_commands.py --run . ${CMAKE_BINARY_DIR} \
    tests/data/pages_bad/bad.md) && exit 1; echo \"$out\"; \
    [ $(grep -c '^FAIL' <<<\"$out\") -eq 6 ] && grep -q 'without a tag' <<<\"$out\" && \
    grep -q 'without --headless' <<<\"$out\" && grep -q \"printed none of \\['shaded_pixels=1'\\]\" <<<\"$out\" && \
    grep -q 'exit 2, expected 0' <<<\"$out\" && grep -q 'short variant' <<<\"$out\" && \
    grep -q 'which no line of the block starts with' <<<\"$out\""
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(pages.commands_refused PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
# Every picture a page's commands write in the course's folder is one git ignores.
add_test(NAME lessons.screenshots_ignored
  COMMAND ${SYSTEM_PYTHON3} ${CMAKE_SOURCE_DIR}/tests/lessons/screenshots_ignored.py ${CMAKE_SOURCE_DIR})
set_tests_properties(lessons.screenshots_ignored PROPERTIES LABELS unit SKIP_RETURN_CODE 77)
# Every golden a page names (an exercise's target) exists.
add_test(NAME lessons.page_goldens
  COMMAND ${SYSTEM_PYTHON3} ${CMAKE_SOURCE_DIR}/tests/lessons/screenshots_ignored.py --goldens ${CMAKE_SOURCE_DIR})
set_tests_properties(lessons.page_goldens PROPERTIES LABELS unit)
# Chapter 00's shading.glsl names no later chapter's feature, and each feature's file is included only
# under its define (tests/lessons/shading_features.py); the check refuses tests/data/shading_bad (a call
# into chapter 14's lookup, chapter 17's file included unconditionally, files included nowhere).
add_test(NAME lessons.shading_features
  COMMAND ${SYSTEM_PYTHON3} ${CMAKE_SOURCE_DIR}/tests/lessons/shading_features.py ${CMAKE_SOURCE_DIR}/shaders)
add_test(NAME lessons.shading_features_refused
  COMMAND ${BASH} -c "out=$(${SYSTEM_PYTHON3} tests/lessons/shading_features.py tests/data/shading_bad) && exit 1; \
    echo \"$out\"; grep -q \"names 'shadow'\" <<<\"$out\" && grep -q 'includes ambient_occlusion.glsl outside' <<<\"$out\" && \
    grep -q 'material_pbr.glsl .* included by none' <<<\"$out\""
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(lessons.shading_features lessons.shading_features_refused PROPERTIES LABELS unit)
