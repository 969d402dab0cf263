# The course's layout as checks: each chapter's lesson is greppable in that chapter first, and each
# page's "what changed" block is the real diff of the two chapter files (tests/lessons/doc_diffs.py).
add_test(NAME lessons.first_in_chapter COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/lessons/run_lessons.sh ${CMAKE_SOURCE_DIR})
find_program(SYSTEM_PYTHON3 python3 PATHS /usr/bin NO_DEFAULT_PATH)
add_test(NAME lessons.what_changed COMMAND ${SYSTEM_PYTHON3} ${CMAKE_SOURCE_DIR}/tests/lessons/doc_diffs.py --check ${CMAKE_SOURCE_DIR})
set_tests_properties(lessons.first_in_chapter lessons.what_changed PROPERTIES LABELS unit)
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
