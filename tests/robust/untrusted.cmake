# Files an attacker names (tests/robust/run_untrusted.sh): a named pipe wherever a path is read, an
# image whose header declares more texels than a scene may decode, one image under many spellings,
# a script that asks for a million frames. Each run is under a timeout, so a hang fails.
#
#   robust.untrusted.fifo           map, mesh file, model, scene, --scene, --script: "not a regular file"
#   robust.untrusted.map_size       a 25,500 x 25,500 PNG header refused before decoding (1 GB ulimit -v)
#   robust.untrusted.map_one_file   six spellings of one map path: one texture (scene_check's count)
#   robust.untrusted.map_truncated  a PNG cut short: the decode's message names SCENE:LINE and the map
#   robust.untrusted.script_frames  `0-999999 key W` refused when read (frames 0..99,999)
foreach(case fifo map_size map_one_file map_truncated script_frames)
  add_test(NAME robust.untrusted.${case}
    COMMAND ${BASH} ${CMAKE_CURRENT_SOURCE_DIR}/robust/run_untrusted.sh ${CMAKE_BINARY_DIR}/bin ${case})
  set_tests_properties(robust.untrusted.${case} PROPERTIES LABELS robust SKIP_RETURN_CODE 77 TIMEOUT 600)
endforeach()
