# The malformed-scene corpus: scene_check must reject every tests/bad/*.scene with the line its
# "# expect:" comment names (see tests/robust/run_bad.sh), and report a missing scene file by its path.
add_test(NAME bad.scenes
  COMMAND ${BASH} ${CMAKE_CURRENT_SOURCE_DIR}/robust/run_bad.sh $<TARGET_FILE:scene_check>
          ${CMAKE_CURRENT_SOURCE_DIR}/bad)
set_tests_properties(bad.scenes PROPERTIES LABELS unit)
