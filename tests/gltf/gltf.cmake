# glTF 2.0 scenes through the model directive (docs/scene-format.md), label golden: every scene of
# tests/gltf/samples.list drawn by chapter 00 (forward) and by deferred chapters at 320x240 must agree
# within 1/255 on 99.99 % of the pixels, the bound every forward agreement of the course uses. The
# course's own tests/models/lights.gltf has a glass pane (alpha mode BLEND), so its deferred side is
# chapter 12, the first to draw glass; the package's samples have no glass and are drawn by chapters
# 11 (clustered) and 12. The samples are skipped when assimp-testmodels is not installed. The loading
# side (counts, refusals) is tests/bad/gltf.expect and tests/unit/test_model_import.c.
foreach(deferred 11_clustered 12_transparency)
  foreach(set course assimp)
    if(set STREQUAL "course" AND deferred STREQUAL "11_clustered")
      continue() # lights.gltf's glass: chapter 11 leaves it out (it says so)
    endif()
    add_test(NAME gltf.${set}_00_vs_${deferred}
      COMMAND ${BASH} ${CMAKE_CURRENT_SOURCE_DIR}/gltf/run_gltf_agreement.sh $<TARGET_FILE:imgdiff>
              ${COURSE_TEST_OUT}/gltf_${deferred} ${CMAKE_SOURCE_DIR} ${set} 1 0.0001
              $<TARGET_FILE:00_forward> $<TARGET_FILE:${deferred}>)
    set(labels golden)
    if(set STREQUAL "course")
      set(labels "golden;sanitize") # one small scene: the asan tree draws it under the sanitizers
    endif()
    set_tests_properties(gltf.${set}_00_vs_${deferred} PROPERTIES LABELS "${labels}" SKIP_RETURN_CODE 77)
  endforeach()
endforeach()
