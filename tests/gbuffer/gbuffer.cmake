# G-buffer layouts (common/render/gbuffer.h, docs/02_mrt_gbuffer.md): --gbuffer LAYOUT, the benchmark's
# sweep of them, and what each layout keeps.
#
#   gbuffer.layouts          tests/gbuffer/test_gbuffer_layouts.c: names, bytes against the bits GL
#                            reports, reversed-Z's depth and chapter 07's frame with it
#   gbuffer.refusals         tests/gbuffer/run_refusals.sh: an unknown layout, and reversed-z where a
#                            chapter's light volumes test standard depth, give exit 2 and one line
#   gbuffer.bench_sweep      tests/gbuffer/run_bench_gbuffer.sh: bench --gbuffer-sweep's output
#   agree.gbuffer_*          every layout's chapter 07 (and 08) agrees with chapter 00 forward
# (the encodings themselves: unit.test_octahedral)

add_executable(test_gbuffer_layouts ${CMAKE_CURRENT_SOURCE_DIR}/gbuffer/test_gbuffer_layouts.c)
target_link_libraries(test_gbuffer_layouts PRIVATE chapters)
set_target_properties(test_gbuffer_layouts PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
add_test(NAME gbuffer.layouts COMMAND test_gbuffer_layouts WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(gbuffer.layouts PROPERTIES LABELS golden SKIP_RETURN_CODE 77)

add_test(NAME gbuffer.refusals
  COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/gbuffer/run_refusals.sh ${CMAKE_BINARY_DIR}/bin
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(gbuffer.refusals PROPERTIES LABELS unit SKIP_RETURN_CODE 77)

if(TARGET bench)
  add_test(NAME gbuffer.bench_sweep
    COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/gbuffer/run_bench_gbuffer.sh $<TARGET_FILE:bench>
            ${CMAKE_BINARY_DIR}/bench-gbuffer
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(gbuffer.bench_sweep PROPERTIES LABELS bench SKIP_RETURN_CODE 77 TIMEOUT 60)
endif()

if(TARGET 07_face_culling AND TARGET 08_stencil_volumes AND TARGET 03_fullscreen_phong)
  # Every layout draws chapter 07's frame as forward does, within the course's bound (1/255 on
  # 99.99 % of pixels; measured at 320x240: at most 1 level everywhere for each of these).
  foreach(layout reference compact compact-d24s8 linear-albedo oct16)
    course_forward_agreement_test(gbuffer_07_${layout} 1 0.0001 07_face_culling --gbuffer ${layout})
  endforeach()
  # oct8's normals are off by up to 0.64 degrees (unit.test_octahedral): the highlights of the
  # shiniest materials (P = 128 and 256) move, up to 6 levels on 0.21 % of the pixels (measured, 158
  # of 76,800), so its bound is 1/255 on 99.7 % of pixels. The course's bound must fail for it.
  course_forward_agreement_test(gbuffer_07_oct8 1 0.003 07_face_culling --gbuffer oct8)
  course_forward_agreement_test(gbuffer_07_oct8_strict 1 0.0001 07_face_culling --gbuffer oct8)
  set_tests_properties(agree.gbuffer_07_oct8_strict PROPERTIES WILL_FAIL TRUE)
  # Chapter 08's stencil in each depth format: D24S8 (compact-d24s8), D32F_S8 (the default, reference).
  foreach(layout compact compact-d24s8 reference)
    course_forward_agreement_test(gbuffer_08_${layout} 1 0.0001 08_stencil_volumes --gbuffer ${layout})
  endforeach()
  # Reversed-Z against the same layout in standard depth, and against forward (chapter 03 rebuilds
  # every position from depth; chapter 07's frame with mirrored volumes is in gbuffer.layouts).
  course_agreement_test(gbuffer_03_reversed_z_vs_standard 1 0.0001
    03_fullscreen_phong --gbuffer reversed-z VS 03_fullscreen_phong --gbuffer compact)
  course_forward_agreement_test(gbuffer_03_reversed_z 1 0.0001 03_fullscreen_phong --gbuffer reversed-z)
  course_agreement_test(gbuffer_02_depth_view_reversed_z 1 0.0001
    02_mrt_gbuffer --view depth --gbuffer reversed-z VS 02_mrt_gbuffer --view depth --gbuffer compact)
endif()
