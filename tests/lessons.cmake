# The course's layout as checks: each chapter's lesson is greppable in that chapter first, and each
# page's "what changed" block is the real diff of the two chapter files (tests/doc_diffs.py).
add_test(NAME lessons.first_in_chapter COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/run_lessons.sh ${CMAKE_SOURCE_DIR})
find_program(SYSTEM_PYTHON3 python3 PATHS /usr/bin NO_DEFAULT_PATH)
add_test(NAME lessons.what_changed COMMAND ${SYSTEM_PYTHON3} ${CMAKE_SOURCE_DIR}/tests/doc_diffs.py --check ${CMAKE_SOURCE_DIR})
set_tests_properties(lessons.first_in_chapter lessons.what_changed PROPERTIES LABELS unit)
# Every measured figure a page shows is a verbatim copy of one dated run in docs/data/
# (scripts/update-docs.sh writes it; tests/doc_generated.py compares).
add_test(NAME lessons.generated_figures
  COMMAND ${SYSTEM_PYTHON3} ${CMAKE_SOURCE_DIR}/tests/doc_generated.py --check ${CMAKE_SOURCE_DIR})
set_tests_properties(lessons.generated_figures PROPERTIES LABELS unit)
# The README's key table is common/keys.c's (tools/key_table prints it).
add_test(NAME lessons.key_table COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/run_key_table.sh
         $<TARGET_FILE:key_table> ${CMAKE_SOURCE_DIR}/README.md)
set_tests_properties(lessons.key_table PROPERTIES LABELS unit)
