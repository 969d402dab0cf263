# Chapter 10: tiled deferred shading, two ways to make the tile lists (a compute shader, or a
# reduction pass and the CPU) and one shading pass. Its default picture has its golden test
# (golden.10_tiled_deferred, from golden.cmake). Here, as checks: "this matches forward", on both
# paths; "the two paths draw the same picture"; "the culling never drops a light" (the picture is
# chapter 03's, whose full-screen pass loops over every light); the hard cases; the work (light-loop
# iterations <= 3x the ideal pairs); --path compute without compute shaders.
#
# Bounds: against forward, 1/255 on 99.99 % of pixels, as chapters 07-09 (the position is rebuilt
# from depth, so a pixel on a cut-off sphere can fall on either side: 0.02 % where 07 and 08 allow it).
# Between the two paths: 0 everywhere. They run the same shading program on lists in the same light
# order; where one list has a light the other has not, that light reaches no pixel of the tile and
# shade_light() returns exactly 0 for it, and x + 0 is x: the same bytes on any GL.
# Against chapter 03: 0 on llvmpipe (the same reconstruction and the same sum in the same order; the
# tiles only leave out zeros), 1/255 on 99.99 % elsewhere (two different programs, which another
# compiler may contract into fused multiply-adds differently).

function(chapter_10_tests)
  set(S ${CMAKE_SOURCE_DIR}/tests/scenes)
  set(CITY ${CMAKE_SOURCE_DIR}/assets/scenes/city.scene)
  set(SPOTS ${CMAKE_SOURCE_DIR}/assets/scenes/spots.scene)
  set(C 10_tiled_deferred)
  if(NOT TARGET ${C} OR NOT TARGET 00_forward)
    return()
  endif()

  # The pictures the page shows: the tiles view and the overdraw view at 256 generated lights (with
  # the scene's 8, every covered tile holds all 8), and the lit picture of the tile-crowd scene.
  course_golden_test(10_tiled_deferred_tiles ${C} 1 0.0001 --lights 256 --view tiles)
  course_golden_test(10_tiled_deferred_overdraw ${C} 1 0.0001 --lights 256 --view overdraw)
  course_golden_test(10_tiled_deferred_crowd_tiles ${C} 1 0.0001 --scene ${S}/tile_crowd.scene --view tiles)

  # The chapter's claim, on each path: chapter 00's picture on the default scene, the city (757
  # lights, 800x800) and the spots scene; and the same picture from both paths.
  foreach(path compute cpu)
    course_agreement_test(10_vs_forward_${path} 1 0.0001 ${C} --path ${path} VS 00_forward)
    course_agreement_test(10_vs_forward_city_800_${path} 1 0.0001,0.0002
      ${C} --path ${path} --size 800x800 --scene ${CITY} VS 00_forward --size 800x800 --scene ${CITY})
    course_agreement_test(10_vs_forward_spots_${path} 1 0.0001 ${C} --path ${path} --scene ${SPOTS}
      VS 00_forward --scene ${SPOTS})
    course_agreement_test(10_vs_forward_lights1024_${path} 1 0.0002 ${C} --path ${path} --lights 1024
      VS 00_forward --lights 1024)
  endforeach()
  course_agreement_test(10_renderer_forward 0 0 ${C} --renderer forward VS 00_forward)
  foreach(case "default|" "lights1024|--lights@1024" "city_800|--size@800x800@--scene@${CITY}"
               "spots|--scene@${SPOTS}" "tiles_view|--lights@256@--view@tiles"
               "overdraw_view|--lights@256@--view@overdraw" "crowd|--scene@${S}/tile_crowd.scene")
    course_case("${case}" name args)
    course_agreement_test(10_paths_same_${name} 0 0 ${C} --path compute ${args} VS ${C} --path cpu ${args})
  endforeach()

  # The hard cases (docs/hard-cases.md, 15), each on both paths, against forward and against chapter
  # 03's loop over every light: the camera inside a light; a light across the near plane (with the
  # camera in another, and alone); lights across the far plane; the same three for spots; a culled and
  # a constant-attenuation light; the exact cut-off (every radius infinite: every light in every
  # tile); HDR and degenerate input; 48 lights in a few tiles, with and without a per-tile limit
  # below that (--tile-lights 16: those tiles overflow and loop over every light); partial tiles at
  # the right and top edges (17x17, 33x7 at 256 small lights) and a 1x1 window.
  foreach(case "inside_volume|--scene@${S}/inside_volume.scene" "near_plane|--scene@${S}/near_plane.scene"
               "near_plane_alone|--scene@${S}/near_plane_alone.scene" "far_plane|--scene@${S}/far_plane.scene"
               "spot_inside|--scene@${S}/spot_inside.scene" "spot_near_plane|--scene@${S}/spot_near_plane.scene"
               "spot_far_plane|--scene@${S}/spot_far_plane.scene" "culled|--scene@${S}/hard_culled.scene"
               "cutoff0|--cutoff@0" "hdr1e6|--scene@${S}/hard_hdr1e6.scene"
               "degenerate|--scene@${S}/hard_degenerate.scene" "crowd|--scene@${S}/tile_crowd.scene"
               "crowd_tile_lights_16|--scene@${S}/tile_crowd.scene@--tile-lights@16"
               "size17x17|--lights@256@--size@17x17" "size33x7|--lights@256@--size@33x7" "size1x1|--size@1x1"
               "windowed|--lights@64@--falloff@windowed" "time3|--lights@64@--time@3")
    course_case("${case}" name args)
    string(REPLACE "--tile-lights;16" "" fwd_args "${args}")
    foreach(path compute cpu)
      # forward: time3 and a few others put a cut-off sphere through a pixel or two (see above)
      course_agreement_test(10_vs_forward_${name}_${path} 1 0.0002 ${C} --path ${path} ${args}
        VS 00_forward ${fwd_args})
      if(TARGET 03_fullscreen_phong)
        course_agreement_test(10_vs_03_${name}_${path} 0,1 0,0.0001 ${C} --path ${path} ${args}
          VS 03_fullscreen_phong ${fwd_args})
      endif()
    endforeach()
  endforeach()
  if(TARGET 03_fullscreen_phong)
    course_agreement_test(10_vs_03_city_800 0,1 0,0.0001 ${C} --size 800x800 --scene ${CITY}
      VS 03_fullscreen_phong --size 800x800 --scene ${CITY})
    course_agreement_test(10_vs_03_lights1024 0,1 0,0.0001 ${C} --lights 1024 VS 03_fullscreen_phong --lights 1024)
  endif()
  # A per-tile limit changes the work, never the picture.
  course_agreement_test(10_tile_lights_16_same_picture 0 0 ${C} --lights 1024 VS ${C} --lights 1024 --tile-lights 16)

  # The overdraw view's heat map adds up to --bench's shaded_pixels (the light-loop iterations, which
  # the chapter counts from its tile lists), on both paths; and the lit view counts the same (lit-run).
  # Kept below the heat map's saturation (16): the scene's 8 lights, a smaller cut-off, 7 spots.
  if(TARGET heat_count)
    foreach(case "default|" "cutoff_0.1|--cutoff@0.1" "spots|--scene@${SPOTS}" "inside|--scene@${S}/inside_volume.scene")
      course_case("${case}" name args)
      foreach(path compute cpu)
        course_overdraw_count_test(10_sum_${name}_${path} lit-run
          $<TARGET_FILE:${C}> ${COURSE_RENDER_ARGS} --path ${path} ${args})
      endforeach()
    endforeach()
  endif()

  # Light-loop iterations <= 3x the ideal pairs on the default scene at 1024 lights (the issue's
  # target; the city too), the chapter's count = the benchmark's copy's, on both paths.
  if(TARGET bench)
    add_test(NAME golden.10_work
      COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/chapters/run_tiled_work.sh $<TARGET_FILE:bench> $<TARGET_FILE:${C}>
              ${COURSE_TEST_OUT}/10_work
      WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
    set_tests_properties(golden.10_work PROPERTIES LABELS golden SKIP_RETURN_CODE 77 TIMEOUT 300)
  endif()

  # --path: compute asked for without compute shaders, and the key L (golden.cmake).
  course_compute_path_tests(10 ${C} path "tile lists")
  # The compute shaders validate as GLSL 4.30 in shaders.glslang (tests/robust/run_glslang.sh).

  # Bad option values are refused with a message naming the option.
  add_test(NAME chapters.10_bad_path COMMAND ${C} --headless --path gpu WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.10_bad_path PROPERTIES LABELS golden
    PASS_REGULAR_EXPRESSION "unknown --path value 'gpu' \\(one of: compute cpu\\)")
  add_test(NAME chapters.10_bad_tile_lights COMMAND ${C} --headless --tile-lights 0 WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.10_bad_tile_lights PROPERTIES LABELS golden SKIP_RETURN_CODE 77
    PASS_REGULAR_EXPRESSION "bad --tile-lights '0'")
endfunction()

chapter_10_tests()
