# The malformed-scene corpus: scene_check must reject every tests/bad/*.scene with the line its
# "# expect:" comment names (see tests/robust/run_bad.sh), and report a missing scene file by its path.
add_test(NAME bad.scenes
  COMMAND ${BASH} ${CMAKE_CURRENT_SOURCE_DIR}/robust/run_bad.sh $<TARGET_FILE:scene_check>
          ${CMAKE_CURRENT_SOURCE_DIR}/bad)
set_tests_properties(bad.scenes PROPERTIES LABELS unit)

# The bad-model corpus (tests/bad/models.expect): the course's own files, and every file of
# assimp-testmodels' invalid/ folder and broken glTF 2.0 samples (skipped when that package is
# missing; scripts/install-deps.sh installs it). scene_check builds each mesh, so this is the model
# path the chapters take; the asan tree runs the same under the sanitizers (label sanitize).
foreach(set course assimp)
  add_test(NAME bad.models_${set}
    COMMAND ${BASH} ${CMAKE_CURRENT_SOURCE_DIR}/robust/run_bad_models.sh $<TARGET_FILE:scene_check>
            ${CMAKE_SOURCE_DIR} ${set})
  set_tests_properties(bad.models_${set} PROPERTIES LABELS "unit;sanitize" SKIP_RETURN_CODE 77)
endforeach()

# The same through the model directive (tests/bad/gltf.expect): the course's glTF files and broken
# variants, and every glTF 2.0 file of assimp-testmodels, good ones with their counts.
foreach(set course assimp)
  add_test(NAME bad.gltf_${set}
    COMMAND ${BASH} ${CMAKE_CURRENT_SOURCE_DIR}/robust/run_bad_models.sh $<TARGET_FILE:scene_check>
            ${CMAKE_SOURCE_DIR} ${set} model)
  set_tests_properties(bad.gltf_${set} PROPERTIES LABELS "unit;sanitize" SKIP_RETURN_CODE 77)
endforeach()
