# Hostile glTF files (tests/robust/hostile_gltf.py): each category an attacker would try is refused
# with one line, within 512 MB and without a hang, and nothing outside the model's folder is opened.
#
#   robust.hostile_gltf_chapter  the same through chapter 19 (the last chapter: every loader a
#                          chapter runs), one small headless frame for the control case
#   robust.hostile_gltf    scene_check on every case, each run's opens logged by the interposer
#                          tests/robust/open_log.c (LD_PRELOAD); in the sanitizer tree the same
#                          cases under AddressSanitizer, LeakSanitizer and UBSan (label sanitize:
#                          no interposer there, which ASan would refuse to follow, and no memory
#                          bound, which its shadow memory would break)
find_program(SYSTEM_PYTHON3 python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(COURSE_SANITIZE)
  add_test(NAME robust.hostile_gltf
    COMMAND ${SYSTEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/robust/hostile_gltf.py $<TARGET_FILE:scene_check>
            --sanitized)
else()
  add_library(open_log SHARED ${CMAKE_CURRENT_SOURCE_DIR}/robust/open_log.c)
  target_link_libraries(open_log PRIVATE ${CMAKE_DL_LIBS})
  set_target_properties(open_log PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  add_test(NAME robust.hostile_gltf
    COMMAND ${SYSTEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/robust/hostile_gltf.py $<TARGET_FILE:scene_check>
            --open-log $<TARGET_FILE:open_log>)
  add_test(NAME robust.hostile_gltf_chapter
    COMMAND ${SYSTEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/robust/hostile_gltf.py
            $<TARGET_FILE:19_image_based_light> --chapter --open-log $<TARGET_FILE:open_log>)
  set_tests_properties(robust.hostile_gltf_chapter PROPERTIES LABELS robust SKIP_RETURN_CODE 77)
endif()
set_tests_properties(robust.hostile_gltf PROPERTIES LABELS "unit;sanitize")
