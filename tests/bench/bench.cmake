# The forward-vs-deferred benchmark (tools/bench.c, docs/compare.md).
# Its helpers live in tools/bench/ so the tools/*.c glob does not make them separate programs.
target_sources(bench PRIVATE
  ${CMAKE_SOURCE_DIR}/tools/bench/bench_error.c
  ${CMAKE_SOURCE_DIR}/tools/bench/bench_gbuffer.c
  ${CMAKE_SOURCE_DIR}/tools/bench/bench_gbuffer_report.c
  ${CMAKE_SOURCE_DIR}/tools/bench/bench_measure.c
  ${CMAKE_SOURCE_DIR}/tools/bench/bench_options.c
  ${CMAKE_SOURCE_DIR}/tools/bench/bench_plots.c
  ${CMAKE_SOURCE_DIR}/tools/bench/bench_renderers.c
  ${CMAKE_SOURCE_DIR}/tools/bench/bench_report.c
  ${CMAKE_SOURCE_DIR}/tools/bench/bench_report_pbr.c
  ${CMAKE_SOURCE_DIR}/tools/bench/bench_run.c
  ${CMAKE_SOURCE_DIR}/tools/bench/bench_state.c
  ${CMAKE_SOURCE_DIR}/tools/bench/bench_storage.c
  ${CMAKE_SOURCE_DIR}/tools/bench/bench_storage_report.c)
# Chapters 17's and 19's passes against chapter 11's lighting (--ambient-sweep).
# Their errors against the exact references (tools/reference/, the tests' too).
target_sources(bench PRIVATE ${CMAKE_SOURCE_DIR}/tools/bench/bench_ambient.c
               ${CMAKE_SOURCE_DIR}/tools/bench/bench_ambient_error.c)

# --quick runs a small sweep; the check is on the output's shape (columns, rows, finite numbers,
# files), never on timings, which depend on the machine. The sweep ends with the PBR rows (pbr_teapots
# and gltf_engine): about 25 s on 2 cores, so the limit leaves room for a busy machine.
add_test(NAME bench.quick
  COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/bench/run_bench_quick.sh $<TARGET_FILE:bench> ${CMAKE_BINARY_DIR}/bench-quick
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(bench.quick PROPERTIES LABELS "bench" SKIP_RETURN_CODE 77 TIMEOUT 120)

# The storage table (--storage, docs/16_visibility_buffer.md): its shape, and the visibility buffer's
# bytes per sample against the issue's target, counted; no timing is checked.
add_test(NAME bench.storage
  COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/bench/run_bench_storage.sh $<TARGET_FILE:bench> ${CMAKE_BINARY_DIR}/bench-storage
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(bench.storage PROPERTIES LABELS "bench" SKIP_RETURN_CODE 77 TIMEOUT 60)
# --ambient-sweep only: chapters 11, 17 and 19 on the default scene and teapots_probes; the output's
# shape (tests/bench/run_bench_ambient.sh), never the timings.
add_test(NAME bench.ambient
  COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/bench/run_bench_ambient.sh $<TARGET_FILE:bench> ${CMAKE_BINARY_DIR}/bench-ambient
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(bench.ambient PROPERTIES LABELS "bench" SKIP_RETURN_CODE 77 TIMEOUT 120)
# Chapters closed and opened again in one process (the sweep reopens them when the material model
# changes): every renderer on a Blinn-Phong scene, then on the PBR teapots, must end cleanly.
add_test(NAME bench.reopen
  COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/bench/run_bench_reopen.sh $<TARGET_FILE:bench> ${CMAKE_BINARY_DIR}/bench-reopen
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(bench.reopen PROPERTIES LABELS "bench" SKIP_RETURN_CODE 77 TIMEOUT 300)

# Signed differences in the reports (tools/bench/bench_format.c): "-157", never "+-157".
target_sources(bench PRIVATE ${CMAKE_SOURCE_DIR}/tools/bench/bench_format.c)
add_executable(test_bench_format ${CMAKE_SOURCE_DIR}/tests/bench/test_bench_format.c
               ${CMAKE_SOURCE_DIR}/tools/bench/bench_format.c)
target_include_directories(test_bench_format PRIVATE ${CMAKE_SOURCE_DIR}/tools/bench ${CMAKE_SOURCE_DIR}/tests/unit)
target_link_libraries(test_bench_format PRIVATE PkgConfig::CMOCKA m)
set_target_properties(test_bench_format PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
add_test(NAME bench.format_signed COMMAND test_bench_format)
set_tests_properties(bench.format_signed PROPERTIES LABELS unit)
