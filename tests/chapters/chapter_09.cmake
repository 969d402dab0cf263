# Chapter 09 (spot lights drawn as cone volumes): the cone mesh, the picture, and the claims "this
# matches forward" on the spots scene and the default scene, and on the hard cases a cone brings
# (docs/09_spot_lights.md, docs/hard-cases.md case 14).

# The cone mesh contains the spot's cone cut by its sphere (GL-free, but its code lives in the GL
# library beside the sphere's: common/render/light_volumes.c).
add_executable(test_cone_mesh ${CMAKE_CURRENT_SOURCE_DIR}/spot/test_cone_mesh.c)
target_link_libraries(test_cone_mesh PRIVATE common PkgConfig::CMOCKA)
set_target_properties(test_cone_mesh PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
add_test(NAME unit.test_cone_mesh COMMAND test_cone_mesh)
set_tests_properties(unit.test_cone_mesh PROPERTIES LABELS unit)

# "The bug is visible": both renders succeed and differ by at least 10/255 somewhere.
function(chapter_09_expect_bug name)
  course_agreement_test(${name} 1 0.0001 ${ARGN})
  set_tests_properties(agree.${name} PROPERTIES PASS_REGULAR_EXPRESSION "imgdiff: max=[1-9][0-9]+ .*-> FAIL")
endfunction()

# Agreement bound: 1/255 on 99.99 % of pixels, as for chapter 07 (the same G-buffer, RGBA16F sum and
# pass state; only the mesh a spot is drawn with changes).
function(chapter_09_tests)
  set(S ${CMAKE_SOURCE_DIR}/tests/scenes)
  set(SPOTS ${CMAKE_SOURCE_DIR}/assets/scenes/spots.scene)
  set(C 09_spot_lights)
  if(NOT TARGET ${C} OR NOT TARGET 00_forward)
    return()
  endif()

  # The pictures the page shows: the spots scene lit, its lighting fragments with cones and with
  # spheres, the volumes (at --cutoff 1, where the spheres are small enough to see the cones inside them),
  # and the cones without their scales.
  course_golden_test(09_spot_lights_spots ${C} 1 0.0001 --scene ${SPOTS})
  course_golden_test(09_spot_lights_spots_overdraw ${C} 1 0.0001 --scene ${SPOTS} --view overdraw)
  course_golden_test(09_spot_lights_spots_overdraw_spheres ${C} 1 0.0001
    --scene ${SPOTS} --view overdraw --spot-volume sphere)
  course_golden_test(09_spot_lights_spots_volumes ${C} 1 0.0001 --scene ${SPOTS} --view volumes --cutoff 1)
  course_golden_test(09_spot_lights_spots_scale_none ${C} 1 0.0001 --scene ${SPOTS} --scale none)

  # The chapter's claim: chapter 00's picture, on the default scene (no spots: the spheres alone) and on
  # the spots scene, moving, at other cut-offs (0: infinite radii, drawn full-screen), with the windowed
  # falloff, at full size; and with the spots drawn as spheres.
  course_forward_agreement_test(09_vs_forward 1 0.0001 ${C})
  course_agreement_test(09_renderer_forward 0 0 ${C} --renderer forward --scene ${SPOTS}
    VS 00_forward --scene ${SPOTS})
  foreach(case "spots|" "spots_time3|--time@3" "spots_time6|--time@6" "spots_cutoff0|--cutoff@0"
               "spots_cutoff0.3|--cutoff@0.3" "spots_windowed|--falloff@windowed" "spots_800|--size@800x600")
    course_case("${case}" name args)
    course_forward_agreement_test(09_vs_forward_${name} 1 0.0001 ${C} --scene ${SPOTS} ${args})
  endforeach()
  course_agreement_test(09_vs_forward_spots_as_spheres 1 0.0001
    ${C} --scene ${SPOTS} --spot-volume sphere VS 00_forward --scene ${SPOTS})

  # The hard cases a cone brings (docs/hard-cases.md, 14): the camera inside a cone, apexes behind the
  # near plane (the camera inside one cone, outside the other), cones across the far plane.
  foreach(scene spot_inside spot_near_plane spot_far_plane)
    course_forward_agreement_test(09_vs_forward_${scene} 1 0.0001 ${C} --scene ${S}/${scene}.scene)
  endforeach()

  # The cone without its scales cuts into the cone: light is lost along the pyramid's faces.
  chapter_09_expect_bug(09_scale_none_loses_light ${C} --scene ${SPOTS} --scale none VS 00_forward --scene ${SPOTS})

  # The cones shade fewer fragments than the spheres, for the same picture; as spheres, the chapter
  # shades exactly what chapter 07 shades.
  if(TARGET 07_face_culling)
    add_test(NAME golden.09_cone_work
      COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/chapters/run_spot_work.sh $<TARGET_FILE:${C}>
              $<TARGET_FILE:07_face_culling> ${SPOTS}
      WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
    set_tests_properties(golden.09_cone_work PROPERTIES LABELS golden SKIP_RETURN_CODE 77)
  endif()

  add_test(NAME chapters.09_bad_spot_volume COMMAND ${C} --headless --spot-volume pyramid
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(chapters.09_bad_spot_volume PROPERTIES LABELS golden
    PASS_REGULAR_EXPRESSION "unknown --spot-volume value 'pyramid' \\(one of: cone sphere\\)")
endfunction()
chapter_09_tests()

# Every renderer shades spots with the same shade_light(): forward's variants (its light lists keep
# a light by its sphere, which holds the cone), chapter 03's full-screen pass, and the volume chapters
# drawing spheres. Chapter 05 overwrites instead of adding up and chapters 05 and 06 have no depth
# clamp (the spots scene's spheres reach beyond its far plane): they are compared on spot_inside.scene,
# one spot whose sphere ends before the far plane. Chapter 04's fixed radius is not the light's.
function(chapter_09_other_chapters)
  set(S ${CMAKE_SOURCE_DIR}/tests/scenes)
  set(SPOTS ${CMAKE_SOURCE_DIR}/assets/scenes/spots.scene)
  if(NOT TARGET 00_forward)
    return()
  endif()
  foreach(variant forward-naive forward-prepass forward-lists)
    course_agreement_test(00_${variant}_spots 1 0.0001
      00_forward --renderer forward --scene ${SPOTS} VS 00_forward --renderer ${variant} --scene ${SPOTS})
  endforeach()
  foreach(chapter 03_fullscreen_phong 07_face_culling 08_stencil_volumes)
    if(TARGET ${chapter})
      string(SUBSTRING ${chapter} 0 2 n)
      course_forward_agreement_test(${n}_vs_forward_spots 1 0.0001 ${chapter} --scene ${SPOTS})
    endif()
  endforeach()
  foreach(chapter 05_attenuation_radius 06_additive_blending 07_face_culling)
    if(TARGET ${chapter})
      string(SUBSTRING ${chapter} 0 2 n)
      course_forward_agreement_test(${n}_vs_forward_spot_inside 1 0.0001 ${chapter} --scene ${S}/spot_inside.scene)
    endif()
  endforeach()
  if(TARGET 07_face_culling)
    foreach(scene spot_near_plane spot_far_plane)
      course_forward_agreement_test(07_vs_forward_${scene} 1 0.0001 07_face_culling --scene ${S}/${scene}.scene)
    endforeach()
  endif()
endfunction()
chapter_09_other_chapters()
