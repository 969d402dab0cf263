# Chapter 11 (clustered deferred and Forward+): the clusters on the CPU, the pictures, and the claims
# "both renderers match forward" and "their light evaluations stay within 3x the ideal"
# (docs/11_clustered.md).

# The grid's GL-free half (common/clusters/cluster_grid.c) is compiled into its unit test, which links the
# GL-free core only.
if(TARGET test_clusters)
  target_sources(test_clusters PRIVATE ${CMAKE_SOURCE_DIR}/common/clusters/cluster_grid.c)
endif()

# Agreement bound: 1/255 on 99.99 % of pixels, as for chapters 07 to 10 (clustered deferred reads the
# same G-buffer; Forward+ shades the same fragments as forward, in the same light order).
function(chapter_11_tests)
  set(S ${CMAKE_SOURCE_DIR}/tests/scenes)
  set(SPOTS ${CMAKE_SOURCE_DIR}/assets/scenes/spots.scene)
  set(CITY ${CMAKE_SOURCE_DIR}/assets/scenes/city.scene)
  set(C 11_clustered)
  if(NOT TARGET ${C} OR NOT TARGET 00_forward)
    return()
  endif()

  # The pictures the page shows (the default scene's lit picture is golden.11_clustered).
  course_golden_test(11_clustered_clusters ${C} 1 0.0001 --view clusters --lights 256)
  course_golden_test(11_clustered_overdraw ${C} 1 0.0001 --view overdraw --lights 256)
  # Exercise 1's picture: 24 slices instead of the cubic default, so each slice is deeper: fewer, wider
  # bands across the floor, and hotter colours (more lights a cluster) towards the far end.
  course_golden_test(11_clustered_clusters_slices24 ${C} 1 0.0001 --view clusters --lights 256 --slices 24)

  # Both renderers against chapter 00: the default scene, the city at full size, the spots, 1024
  # generated lights; the hard cases (camera inside a light, a light across the near plane, lights
  # across and beyond the far plane, spots across both planes); a 1x1 and a 17x17 window; the exact
  # picture (--cutoff 0: infinite radii, in every cluster); a tiny list limit (overflowing clusters
  # loop over every light).
  foreach(renderer deferred forward-plus)
    set(R --renderer ${renderer})
    set(n ${renderer})
    course_agreement_test(11_${n}_vs_forward 1 0.0001 ${C} ${R} VS 00_forward)
    course_agreement_test(11_${n}_vs_forward_city 1 0.0001
      ${C} ${R} --scene ${CITY} --size 800x800 VS 00_forward --scene ${CITY} --size 800x800)
    course_agreement_test(11_${n}_vs_forward_spots 1 0.0001 ${C} ${R} --scene ${SPOTS} VS 00_forward --scene ${SPOTS})
    course_agreement_test(11_${n}_vs_forward_lights1024 1 0.0001
      ${C} ${R} --lights 1024 VS 00_forward --lights 1024)
    foreach(scene inside_volume near_plane far_plane clustered_beyond_far spot_near_plane spot_far_plane)
      course_agreement_test(11_${n}_vs_forward_${scene} 1 0.0001
        ${C} ${R} --scene ${S}/${scene}.scene VS 00_forward --scene ${S}/${scene}.scene)
    endforeach()
    course_agreement_test(11_${n}_vs_forward_1x1 1 0.0001 ${C} ${R} --size 1x1 VS 00_forward --size 1x1)
    course_agreement_test(11_${n}_vs_forward_17x17 1 0.0001
      ${C} ${R} --size 17x17 --lights 64 VS 00_forward --size 17x17 --lights 64)
    course_agreement_test(11_${n}_vs_forward_cutoff0 1 0.0001 ${C} ${R} --cutoff 0 VS 00_forward --cutoff 0)
    course_agreement_test(11_${n}_vs_forward_overflow 1 0.0001
      ${C} ${R} --lights 256 --cluster-lights 2 VS 00_forward --lights 256)
  endforeach()
  # Chapter 00 lists Forward+ among its renderers: through the renderer table (app_render_forward),
  # chapter 11's forward renderer draws the same picture.
  course_agreement_test(11_renderer_table_forward_plus 0 0
    ${C} --renderer forward-plus --lights 256 VS ${C} --renderer forward --lights 256)

  # The light lists from the compute passes (--assign compute) are the CPU's, bit for bit: --assign
  # check reads them back every frame and compares them with cluster_lists_assign's on the same view
  # (exit 1, naming the first cluster that differs). Exact, not within a bound: both take the same
  # candidate clusters (cluster_grid_sphere_slices and _tiles, on the CPU) and the shader's
  # sphere-against-box test adds up the same floats in the same order (`precise`: no fused
  # multiply-add). Then both renderers draw the same bytes from either list.
  set(assign_cases
    "default" ""
    "lights1024" "--lights 1024"
    "city" "--scene ${CITY} --size 800x800"
    "spots" "--scene ${SPOTS}"
    "cutoff0" "--cutoff 0"
    "overflow" "--lights 256 --cluster-lights 2")
  foreach(scene inside_volume near_plane far_plane clustered_beyond_far spot_near_plane spot_far_plane)
    list(APPEND assign_cases ${scene} "--scene ${S}/${scene}.scene")
  endforeach()
  list(LENGTH assign_cases n_cases)
  math(EXPR last "${n_cases} - 1")
  foreach(i RANGE 0 ${last} 2)
    math(EXPR j "${i} + 1")
    list(GET assign_cases ${i} name)
    list(GET assign_cases ${j} args)
    separate_arguments(args UNIX_COMMAND "${args}")
    add_test(NAME chapters.11_assign_same_${name}
      COMMAND ${C} --headless --frames 1 --gl-debug --assign check ${args} WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
    set_tests_properties(chapters.11_assign_same_${name} PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
    foreach(renderer deferred forward-plus)
      course_agreement_test(11_${renderer}_assign_cpu_vs_compute_${name} 0 0
        ${C} --renderer ${renderer} --assign cpu ${args} VS ${C} --renderer ${renderer} --assign compute ${args})
    endforeach()
  endforeach()
  # --assign: compute asked for without compute shaders, and the key L (golden.cmake).
  course_compute_path_tests(11 ${C} assign "light assignment")

  # The work: at most 3x the ideal (pixel, light) pairs, never fewer; the chapter and the benchmark's
  # two renderers count the same.
  if(TARGET bench)
    add_test(NAME golden.11_work
      COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/chapters/run_clustered_work.sh $<TARGET_FILE:bench>
              $<TARGET_FILE:${C}> ${COURSE_TEST_OUT}/11_work
      WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
    set_tests_properties(golden.11_work PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
  endif()

  add_test(NAME chapters.11_bad_slices COMMAND ${C} --headless --slices 0 WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.11_bad_slices PROPERTIES LABELS golden WILL_FAIL TRUE)
endfunction()
chapter_11_tests()

# Forward+ is the strongest forward, so every chapter that offers `forward` offers it too (the runner
# adds it after `forward`): the same renderer through the same table, so the same bytes as forward.
foreach(chapter 01_fbo_setup 02_mrt_gbuffer 03_fullscreen_phong 07_face_culling 08_stencil_volumes
                09_spot_lights 10_tiled_deferred 12_transparency)
  if(TARGET ${chapter} AND TARGET 00_forward AND TARGET 11_clustered)
    course_agreement_test(${chapter}_forward_plus 0 0 ${chapter} --renderer forward-plus VS 00_forward --renderer forward)
  endif()
endforeach()
