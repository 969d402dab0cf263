# Fuzzing every input the course reads: the scene format (scene_parse_string), the command line
# (cli_parse), the --script format (input_script_parse) and model files (mesh_data_load_memory,
# Assimp included). Targets and seeds live in tests/fuzz/; see docs/testing.md.
#
#   fuzz.replay.TARGET (label unit): the seeds and every saved crash in
#       tests/fuzz/regressions/ replayed through the target with this tree's compiler (and its
#       sanitizers, in the asan tree).
#   fuzz.TARGET (label fuzz): a short libFuzzer run, compiled with clang by run_fuzz.sh,
#       when clang is installed.
#   fuzz.valgrind.model (label unit): the model replay under valgrind, for writes inside Assimp.
#   COURSE_FUZZ=ON with clang (preset `fuzz`): build/bin/fuzz_TARGET for long runs.
set(COURSE_FUZZ_TARGETS scene cli script model)
set(COURSE_FUZZ_SECONDS_scene 20)
set(COURSE_FUZZ_SECONDS_cli 6)
set(COURSE_FUZZ_SECONDS_script 6)
set(COURSE_FUZZ_SECONDS_model 10)

foreach(target ${COURSE_FUZZ_TARGETS})
  add_executable(fuzz_${target}_replay ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_${target}.c
                 ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/replay_main.c)
  target_link_libraries(fuzz_${target}_replay PRIVATE common_core)
  set_target_properties(fuzz_${target}_replay PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  add_test(NAME fuzz.replay.${target}
    COMMAND fuzz_${target}_replay ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus_${target}
            ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/regressions/${target})
  set_tests_properties(fuzz.replay.${target} PROPERTIES LABELS unit)
endforeach()

# The model target writes each glTF input to a folder of its own under $TMPDIR: it must leave nothing
# behind. The open() interposer (tests/robust/open_log.c) shows that it did write there.
if(NOT COURSE_SANITIZE)
  add_test(NAME fuzz.replay.model_cleans_up
    COMMAND ${BASH} -c "tmp=$(mktemp -d) && mkdir $tmp/t && TMPDIR=$tmp/t OPEN_LOG=$tmp/opens LD_PRELOAD=$2 \"$0\" \"$1\" \
>/dev/null 2>&1; rc=$?; used=$(grep -c \"^$tmp/t/fuzz_model_\" $tmp/opens); left=$(ls -A $tmp/t); rm -rf $tmp; \
echo \"exit $rc, $used files written under TMPDIR, left there: '$left'\"; [ $rc -eq 0 ] && [ $used -gt 0 ] && [ -z \"$left\" ]"
            $<TARGET_FILE:fuzz_model_replay> ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus_model $<TARGET_FILE:open_log>)
  set_tests_properties(fuzz.replay.model_cleans_up PROPERTIES LABELS unit)
endif()

# Assimp is a shared library the sanitizers do not instrument: AddressSanitizer misses a write
# past a block inside it (the PLY reader's, tests/fuzz/regressions/model/heap-ply-*, showed up only
# as damage to ASan's own bookkeeping, minutes later). valgrind sees every byte: this replays the
# model seeds and regressions through the uninstrumented replay binary and fails on any invalid
# read or write. Not in a sanitizer tree (valgrind cannot run those binaries).
find_program(COURSE_VALGRIND valgrind)
if(COURSE_VALGRIND AND NOT COURSE_SANITIZE)
  add_test(NAME fuzz.valgrind.model
    COMMAND ${COURSE_VALGRIND} -q --error-exitcode=1 --leak-check=no $<TARGET_FILE:fuzz_model_replay>
            ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus_model ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/regressions/model)
  set_tests_properties(fuzz.valgrind.model PROPERTIES LABELS unit)
endif()

if(COURSE_FUZZ)
  if(NOT CMAKE_C_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "COURSE_FUZZ=ON needs clang: configure with -DCMAKE_C_COMPILER=clang (preset fuzz)")
  endif()
  # The parser is compiled into the target (not linked from common_core) so that it carries
  # libFuzzer's coverage instrumentation too.
  set(COURSE_FUZZ_SOURCES_scene ${CMAKE_SOURCE_DIR}/common/scene/scene.c ${CMAKE_SOURCE_DIR}/common/scene/scene_parser.c
    ${CMAKE_SOURCE_DIR}/common/scene/scene_directives.c ${CMAKE_SOURCE_DIR}/common/scene/scene_materials.c
    ${CMAKE_SOURCE_DIR}/common/scene/scene_lights.c
    ${CMAKE_SOURCE_DIR}/common/scene/scene_model.c ${CMAKE_SOURCE_DIR}/common/scene/model_import.c
    ${CMAKE_SOURCE_DIR}/common/scene/model_image.c
    ${CMAKE_SOURCE_DIR}/common/model/model_file.c ${CMAKE_SOURCE_DIR}/common/model/model_scan.c ${CMAKE_SOURCE_DIR}/common/model/model_gltf.c ${CMAKE_SOURCE_DIR}/common/model/model_gltf_parts.c
    ${CMAKE_SOURCE_DIR}/common/scene/mesh_data.c ${CMAKE_SOURCE_DIR}/common/scene/mesh_tangents.c
    ${CMAKE_SOURCE_DIR}/common/base/log.c ${CMAKE_SOURCE_DIR}/common/base/data_dir.c)
  set(COURSE_FUZZ_SOURCES_cli ${CMAKE_SOURCE_DIR}/common/platform/cli.c ${CMAKE_SOURCE_DIR}/common/platform/cli_help.c ${CMAKE_SOURCE_DIR}/common/platform/input_script.c
    ${CMAKE_SOURCE_DIR}/common/platform/input.c ${CMAKE_SOURCE_DIR}/common/base/gbuffer_layout_names.c
    ${CMAKE_SOURCE_DIR}/common/platform/keys.c ${CMAKE_SOURCE_DIR}/common/base/progress.c
    ${CMAKE_SOURCE_DIR}/common/base/log.c ${CMAKE_SOURCE_DIR}/common/base/data_dir.c
    ${CMAKE_SOURCE_DIR}/common/base/image.c) # a script's screenshot names an image format
  set(COURSE_FUZZ_SOURCES_script ${COURSE_FUZZ_SOURCES_cli})
  set(COURSE_FUZZ_SOURCES_model ${COURSE_FUZZ_SOURCES_scene}) # the scene parser reads models too
  foreach(target ${COURSE_FUZZ_TARGETS})
    add_executable(fuzz_${target} ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_${target}.c
                   ${COURSE_FUZZ_SOURCES_${target}})
    target_include_directories(fuzz_${target} PRIVATE ${COMMON_INCLUDE_DIRS})
    target_link_libraries(fuzz_${target} PRIVATE PkgConfig::CGLM PkgConfig::ASSIMP PkgConfig::STB PkgConfig::CJSON Threads::Threads m)
    target_compile_options(fuzz_${target} PRIVATE -fsanitize=fuzzer,address,undefined
                           -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
    target_link_options(fuzz_${target} PRIVATE -fsanitize=fuzzer,address,undefined)
  endforeach()
endif()

find_program(COURSE_CLANG clang)
if(COURSE_CLANG)
  foreach(target ${COURSE_FUZZ_TARGETS})
    add_test(NAME fuzz.${target}
      COMMAND ${BASH} ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/run_fuzz.sh ${CMAKE_SOURCE_DIR} ${target}
              ${COURSE_FUZZ_SECONDS_${target}} ${CMAKE_BINARY_DIR}/test-out/fuzz-${target})
    # A high COST makes ctest start the long runs first, beside the short tests, not after them.
    set_tests_properties(fuzz.${target} PROPERTIES LABELS fuzz SKIP_RETURN_CODE 77 COST 1000
      ENVIRONMENT "FUZZ_CC=${COURSE_CLANG}")
  endforeach()
endif()
