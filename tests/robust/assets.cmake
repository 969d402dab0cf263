# The committed scenes are reproducible from tools/gen_scenes, and all of them parse.
add_test(NAME assets.reproducible
  COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/robust/run_assets.sh $<TARGET_FILE:gen_scenes> $<TARGET_FILE:scene_check>
          ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/regen)
set_tests_properties(assets.reproducible PROPERTIES LABELS unit)
