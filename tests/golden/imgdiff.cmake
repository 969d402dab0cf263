# tools/imgdiff: exit status and heat-map files on small committed fixtures (tests/data):
#   a.png        16x12 gradient
#   b_close.png  every channel off by exactly 1
#   b_far.png    three pixels off by 40, inside the block that mask.png excludes
#   small.png    8x8, for the size mismatch
if(TARGET imgdiff)
  set(IMGDIFF_DATA ${CMAKE_CURRENT_SOURCE_DIR}/data)
  set(IMGDIFF_OUT ${CMAKE_CURRENT_BINARY_DIR}/imgdiff)
  set(IMGDIFF_RUN ${BASH} ${CMAKE_CURRENT_SOURCE_DIR}/golden/run_imgdiff.sh)

  function(imgdiff_test name)
    add_test(NAME imgdiff.${name} COMMAND ${IMGDIFF_RUN} ${ARGN})
    set_tests_properties(imgdiff.${name} PROPERTIES LABELS unit)
  endfunction()

  imgdiff_test(identical 0 -- $<TARGET_FILE:imgdiff> ${IMGDIFF_DATA}/a.png ${IMGDIFF_DATA}/a.png)
  # The default tolerance of 1 absorbs rounding differences between drivers.
  imgdiff_test(within_tolerance 0 --no-file ${IMGDIFF_OUT}/close_heat.png
    -- $<TARGET_FILE:imgdiff> --heatmap-on-fail ${IMGDIFF_OUT}/close_heat.png
    ${IMGDIFF_DATA}/a.png ${IMGDIFF_DATA}/b_close.png)
  imgdiff_test(zero_tolerance 1
    -- $<TARGET_FILE:imgdiff> --tolerance 0 ${IMGDIFF_DATA}/a.png ${IMGDIFF_DATA}/b_close.png)
  imgdiff_test(far_fails 1 --creates ${IMGDIFF_OUT}/far_heat.png
    -- $<TARGET_FILE:imgdiff> --heatmap-on-fail ${IMGDIFF_OUT}/far_heat.png
    ${IMGDIFF_DATA}/a.png ${IMGDIFF_DATA}/b_far.png)
  imgdiff_test(heatmap_always 0 --creates ${IMGDIFF_OUT}/same_heat.png
    -- $<TARGET_FILE:imgdiff> --heatmap ${IMGDIFF_OUT}/same_heat.png
    ${IMGDIFF_DATA}/a.png ${IMGDIFF_DATA}/a.png)
  # 3 of 192 pixels (1.6 %) are over: allowed by 2 %, not by 1 %.
  imgdiff_test(fraction_allows 0
    -- $<TARGET_FILE:imgdiff> --max-fraction 0.02 ${IMGDIFF_DATA}/a.png ${IMGDIFF_DATA}/b_far.png)
  imgdiff_test(fraction_rejects 1
    -- $<TARGET_FILE:imgdiff> --max-fraction 0.01 ${IMGDIFF_DATA}/a.png ${IMGDIFF_DATA}/b_far.png)
  imgdiff_test(mask_excludes 0
    -- $<TARGET_FILE:imgdiff> --tolerance 0 --mask ${IMGDIFF_DATA}/mask.png
    ${IMGDIFF_DATA}/a.png ${IMGDIFF_DATA}/b_far.png)
  imgdiff_test(missing_file 2 --says no_such_file.png
    -- $<TARGET_FILE:imgdiff> ${IMGDIFF_DATA}/a.png ${IMGDIFF_OUT}/no_such_file.png)
  imgdiff_test(size_mismatch 2 --says "16x12 vs 8x8"
    -- $<TARGET_FILE:imgdiff> ${IMGDIFF_DATA}/a.png ${IMGDIFF_DATA}/small.png)
  imgdiff_test(bad_usage 2 -- $<TARGET_FILE:imgdiff> --tolerance many ${IMGDIFF_DATA}/a.png)
endif()
