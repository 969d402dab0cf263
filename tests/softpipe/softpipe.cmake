# A second driver: every golden and agreement test (course_golden_test, course_agreement_test and
# course_forward_agreement_test, tests/golden/golden.cmake) runs a second time as softpipe.TEST on
# Mesa's softpipe (GALLIUM_DRIVER=softpipe): another rasterizer, another shader back end (an
# interpreter, in float, where llvmpipe compiles with LLVM), a GL 3.3 context with GL_MAX_SAMPLES 1
# and GL_MAX_TEXTURE_BUFFER_SIZE 65,536 (llvmpipe: 4.5, 4 samples, 134 million texels).
# tests/softpipe/run_softpipe.sh checks that each command really gets softpipe (otherwise: skipped)
# and skips a test whose chapter refuses what the context lacks (compute shaders, 4 samples).
#
#   ctest -C softpipe -L softpipe    the whole set (CONFIGURATIONS softpipe keeps it out of a plain
#                                    ctest: 54 to 82 minutes on 2 cores, docs/testing.md)
#   ctest -L softpipe-ci             the quick subset, which a plain ctest also runs
#
# A softpipe test keeps its llvmpipe bound (the first of "LLVMPIPE,OTHER") unless a bound below says
# otherwise; the llvmpipe tests themselves are untouched. Each bound below was measured on softpipe
# (Mesa 22.3.6) against the llvmpipe golden or between the two renderings, with its reason above it.
# Two kinds: where the drivers differ by a few levels over many pixels (float precision), a larger
# tolerance, the smallest that leaves no more than llvmpipe's 0.01 % over it; where they differ
# all-or-nothing on some pixels (which side of an edge, a line or a threshold a pixel falls), the
# same tolerance with the measured share of pixels, rounded up to two significant figures.
# tests/softpipe/measure.sh gives both figures for a test's last softpipe run.

# course_softpipe_bound(TEST TOLERANCE MAX_FRACTION): softpipe's own bound for TEST (golden.NAME or
# agree.NAME).
function(course_softpipe_bound test tolerance fraction)
  set_property(GLOBAL PROPERTY COURSE_SOFTPIPE_BOUND_${test} "${tolerance};${fraction}")
  set_property(GLOBAL APPEND PROPERTY COURSE_SOFTPIPE_NAMED ${test})
endfunction()

# course_softpipe_known_difference(TEST REASON): TEST's pictures differ on softpipe for a reason that
# is not precision (a driver bug, a limit the course does not handle): softpipe.TEST passes only while
# they still differ beyond the bound (imgdiff's FAIL), so it fails, and says so, once the cause is gone.
function(course_softpipe_known_difference test reason)
  set_property(GLOBAL PROPERTY COURSE_SOFTPIPE_KNOWN_${test} "${reason}")
  set_property(GLOBAL APPEND PROPERTY COURSE_SOFTPIPE_NAMED ${test})
endfunction()

# course_softpipe_unchecked(TEST REASON): what TEST claims cannot be seen on softpipe (both sides
# draw the same wrong picture, or the picture is made of llvmpipe's rounding, so it would pass for
# nothing or for anything): softpipe.TEST is skipped, with REASON.
function(course_softpipe_unchecked test reason)
  set_property(GLOBAL PROPERTY COURSE_SOFTPIPE_UNCHECKED_${test} "${reason}")
  set_property(GLOBAL APPEND PROPERTY COURSE_SOFTPIPE_NAMED ${test})
endfunction()

# Lines: the volumes views draw each light volume's wire frame. softpipe draws a line from its
# end points truncated to whole pixels, one pixel a step (sp_setup_line), llvmpipe with the
# diamond-exit rule of GL's line rasterization, so most lines land one pixel apart; measured
# 6,869 (03, 07), 7,254 (04) and 5,442 (09) pixels of 76,800 at up to 255/255, all on the lines
# (the rest within 1/255).
course_softpipe_bound(golden.03_fullscreen_phong_volumes 1 0.09)
course_softpipe_bound(golden.04_light_volumes_volumes 1 0.095)
course_softpipe_bound(golden.07_face_culling_volumes 1 0.09)
course_softpipe_bound(golden.09_spot_lights_spots_volumes 1 0.071)

# A threshold on a derivative: the ring view adds the ring where the light's radius minus the
# distance is under 1.5 fwidth(distance) (light_volume.frag); the drivers' derivatives and
# reconstructed positions differ in the last bits (10 % of pixels by 1/255, within the bound), so
# the ring's edge pixels fall either way: 44 pixels (87 at cut-off 0.3), up to 239/255.
course_softpipe_bound(golden.05_attenuation_radius_ring 1 0.00058)
course_softpipe_bound(golden.05_attenuation_radius_ring_0.15 1 0.00058)
course_softpipe_bound(golden.05_attenuation_radius_ring_0.3 1 0.0012)

# 8-bit blending: the rgba8 exercise adds every light into an RGBA8 target, rounding at each light;
# llvmpipe blends the 8-bit values in fixed point, softpipe blends in float and rounds the sum (how
# 8-bit blending rounds is each implementation's own: the test's bound for GPUs is 255); summed
# over the overlaps and stretched by the tone map: 59 % of pixels differ, 4 by more than 7/255
# (947 by more than 4), at most 43.
course_softpipe_bound(golden.06_additive_blending_rgba8_reinhard 7 0.0001)

# softpipe's GL_MAX_TEXTURE_BUFFER_SIZE is 65,536, GL 3.3's minimum: chapter 11 gives each of the
# 4,160 clusters at 320 x 240 room for 65,536 / 4,160 = 15 lights (list_limit), and a cluster with more
# loops over every light, so its count shows as the overflow colour (llvmpipe: no limit): the two
# clusters on the red and the green boxes, 1,618 pixels, in both views.
course_softpipe_bound(golden.11_clustered_clusters 1 0.022)
course_softpipe_bound(golden.11_clustered_overdraw 1 0.022)
# At 800 x 800 the city has 25 x 25 tiles x 156 slices = 97,500 clusters, more than the texture
# buffer can address: list_limit falls to 0 (then 1), the cluster ranges past texel 65,536 read 0,
# and the frame has no light at all (--bench: shaded_pixels=0). A limit chapter 11 does not check
# yet: it should refuse or coarsen the grid (at 560 x 560, 36,612 clusters, it is right, and slow).
course_softpipe_known_difference(agree.11_deferred_vs_forward_city
  "97,500 clusters exceed softpipe's GL_MAX_TEXTURE_BUFFER_SIZE of 65,536: no light reaches the frame")
course_softpipe_known_difference(agree.11_forward-plus_vs_forward_city
  "97,500 clusters exceed softpipe's GL_MAX_TEXTURE_BUFFER_SIZE of 65,536: no light reaches the frame")

# Shadows: a surface shadows itself unless its depth stays behind the atlas's by the bias, and on
# the floor at grazing angles and along the cube faces' edges the two are within the last bits. The
# drivers rasterize the atlas's depth (and glPolygonOffset's slope term) and interpolate the
# receiver's position differently (softpipe evaluates each attribute's plane from the window's
# origin, which sp_setup.c's own comment says loses low bits): the default scene's atlas view differs
# on 20 pixels by at most 4/255, yet with the chapter's slope bias 1.8 % of the default frame's
# pixels take the other side of the test (53 % with --slope-bias 0), all-or-nothing, up to 104/255.
# Measured:
course_softpipe_bound(golden.14_shadows 1 0.018)               # 1,379 pixels, max 104
course_softpipe_bound(golden.14_shadows_teapots 1 0.018)       # 1,347, max 42
course_softpipe_bound(golden.14_shadows_spots 1 0.0025)        # 187, max 147
course_softpipe_bound(golden.14_shadows_pcf3 1 0.032)          # 2,387, max 94
course_softpipe_bound(golden.14_shadows_contact 1 0.0057)      # 437, max 137
course_softpipe_bound(golden.14_shadows_visibility 1 0.00073)  # 56, max 233
course_softpipe_bound(golden.14_shadows_importance 1 0.016)    # 1,156, max 42 (the lit teapots under discs)
course_softpipe_bound(golden.14_shadows_grazing 1 0.00054)     # 41, max 43
course_softpipe_bound(golden.19_image_based_light_teapots_shadows 1 0.018) # 1,345, max 43
course_softpipe_bound(agree.14_vs_forward_d16 1 0.0059)        # 446, max 48: 16-bit depth, less room still
# Without the normal offset and the slope bias the grazing floor is all acne, and acne is the
# pattern of those last bits themselves: 62 % of pixels differ (47,706 over 1/255, up to 208), so a
# bound would hold anything; what the golden shows (acne there) is llvmpipe's rounding to the pixel.
course_softpipe_unchecked(golden.14_shadows_grazing_acne
  "the acne's pattern is each driver's own rounding (62 % of pixels differ): nothing to compare")
# The atlas view shows one texel a pixel, texelFetch at the interpolated tile coordinate truncated
# (shadow_debug.frag): where that coordinate lands on a texel's edge the drivers pick neighbours,
# and at a depth edge those differ: 4,739 pixels, in streaks along the edges, up to 196/255.
course_softpipe_bound(golden.14_shadows_atlas 1 0.062)
# Deferred against forward with shadows on softpipe: the deferred side looks up the shadow at the
# position rebuilt from depth, forward at the interpolated one, and softpipe's interpolation keeps
# fewer low bits than llvmpipe's; with PCF the taps blend smoothly, so the difference is a few levels:
# over 1/255 on 9 (pcf3), 8 (pcf5), 11 and 12 pixels, over 2/255 on 5, 1, 7 and 6.
course_softpipe_bound(agree.14_vs_forward_pcf3 2 0.0001)
course_softpipe_bound(agree.14_vs_forward_pcf5 2 0.0001)
course_softpipe_bound(agree.15_shadows_vs_forward_pbr_teapots 2 0.0001)
course_softpipe_bound(agree.18_shadows_vs_forward 2 0.0001)

# Textured metallic-roughness materials: each driver samples the material images its own way
# (softpipe's sampler in float, sp_tex_sample.c; llvmpipe's generated code, with its own
# level-of-detail and filter arithmetic); not the anisotropic filter (with --anisotropy 1 the two
# differ more, 3.5 % of the albedo view's pixels over 1/255 instead of 0.4 %). The channel views
# differ by a few levels (plus the teapot rim's edge pixel at (134,186), covered by one rasterizer
# only): the smallest tolerance that leaves at most 0.01 % of pixels over it.
course_softpipe_bound(golden.18_pbr_albedo 2 0.0001)     # 154 pixels over 1/255, 6 over 2/255
course_softpipe_bound(golden.18_pbr_metallic 2 0.0001)   # 9 over 1, 6 over 2 (the rim pixel: 255)
course_softpipe_bound(golden.18_pbr_emissive 2 0.0001)   # 44 over 1, 1 over 2, max 4
course_softpipe_bound(golden.18_pbr_normal 4 0.0001)     # 6,240 over 1, 60 over 3, 6 over 4
course_softpipe_bound(golden.18_pbr_occlusion 4 0.0001)  # 2,935 over 1, 17 over 3, 7 over 4
course_softpipe_bound(golden.18_pbr_roughness 5 0.0001)  # 592 over 1, 9 over 4, 4 over 5
course_softpipe_bound(golden.19_image_based_light_pbr_ssao 5 0.0001) # 55 over 2, 13 over 4, 7 over 5
# Lit, the narrow GGX highlights of the polished teapots magnify those differences through the
# normal maps (as chapter_16.cmake says of its two renderers on llvmpipe): no small
# tolerance holds them (406 pixels over 8/255 on the teapots), so the measured share at the test's.
course_softpipe_bound(golden.18_pbr_teapots 1 0.048)         # 3,632 pixels over 1/255, max 70
course_softpipe_bound(golden.18_pbr_exposure4 2 0.044)       # 3,337 over 2/255, max 105
course_softpipe_bound(golden.15_light_prepass_pbr_teapots 1 0.047) # 3,576 over 1/255, max 71

# SSAO: the occlusion compares sample depths with the surface's, and at the edge pixel (148,99) the
# two rasterizers disagree on which surface is there (chapter 03's one pixel, 84/255 here): at most
# 3 pixels over 2/255 (14 and 8 over 1/255).
course_softpipe_bound(golden.17_ssao_radius2 2 0.0001)
course_softpipe_bound(golden.17_ssao_boxes 2 0.0001)

# Chapter 16 on softpipe draws no visibility pass at all: Mesa 22.3.6's softpipe writes no fragment
# of a draw whose fragment shader reads gl_PrimitiveID without a geometry shader, and raises no GL
# error (a 40-line EGL program: an R32UI target cleared to 0x55 keeps 0x55, llvmpipe writes the ids;
# the same shader without gl_PrimitiveID draws). Every id is the background: the lit view is black.
foreach(test golden.16_visibility_buffer golden.16_visibility_buffer_ids agree.16_vs_forward_default
    agree.16_vs_forward_800 agree.16_vs_forward_edge_on agree.16_vs_forward_near agree.16_vs_forward_pbr
    agree.16_vs_forward_spots agree.16_vs_forward_teapots agree.16_vs_forward_time3 agree.16_bunnies_max
    agree.16_bunnies_count agree.16_shadows_vs_forward_teapots agree.18_emissive_16)
  course_softpipe_known_difference(${test}
    "softpipe drops every fragment that reads gl_PrimitiveID without a geometry shader: no ids")
endforeach()
# and so these compare two pictures the bug makes alike (or different) whatever the chapter does:
foreach(test agree.16_samples1 agree.16_vis_pass_full agree.16_shadows_differ agree.16_pbr_aniso_differs
    agree.16_vis_pass_no_primitive_id_differs agree.16_vis_pass_no_primitive_id_ids_differ)
  course_softpipe_unchecked(${test}
    "softpipe draws no visibility pass (gl_PrimitiveID, tests/softpipe/softpipe.cmake): nothing to compare")
endforeach()

# The quick subset (label softpipe-ci, in every plain ctest run; 15 to 33 s at -j2, docs/testing.md):
# one golden per chapter family, each on its default scene, the per-driver bounds of lines, shadows
# and textures, a known difference, and agreements of the course's main claims (deferred is
# forward, OSMesa is EGL, overwriting is wrong).
set(COURSE_SOFTPIPE_CI
  golden.00_forward golden.03_fullscreen_phong golden.05_attenuation_radius golden.07_face_culling
  golden.08_stencil_volumes golden.09_spot_lights_spots golden.10_tiled_deferred golden.11_clustered
  golden.12_transparency_glass golden.13_msaa_samples1 golden.14_shadows golden.15_light_prepass
  golden.16_visibility_buffer golden.17_ssao golden.18_pbr_albedo golden.19_image_based_light_size32
  golden.07_face_culling_volumes
  agree.00_osmesa_vs_egl agree.03_vs_forward agree.04_overwrite_differs agree.06_vs_forward
  agree.10_vs_forward_cpu agree.11_deferred_vs_forward agree.14_vs_forward_spot)

# Registers softpipe.TEST for every recorded test; deferred to the end of tests/CMakeLists.txt so that
# every module has added its tests and their properties (a "differs" test's PASS_REGULAR_EXPRESSION).
function(course_softpipe_register_all)
  get_property(tests GLOBAL PROPERTY COURSE_SOFTPIPE_TESTS)
  foreach(test ${tests})
    get_property(args GLOBAL PROPERTY COURSE_SOFTPIPE_ARGS_${test})
    list(POP_FRONT args kind name)
    if(kind STREQUAL "golden")
      list(POP_FRONT args golden tolerance fraction)
      set(head ${name} ${golden})
    else()
      list(POP_FRONT args tolerance fraction)
      set(head ${name})
    endif()
    get_property(bound GLOBAL PROPERTY COURSE_SOFTPIPE_BOUND_${test})
    if(bound)
      list(GET bound 0 tolerance)
      list(GET bound 1 fraction)
    else()
      # llvmpipe's bound: the first of "LLVMPIPE,OTHER" (tests/golden/renderer_bounds.sh).
      string(REGEX REPLACE ",.*" "" tolerance "${tolerance}")
      string(REGEX REPLACE ",.*" "" fraction "${fraction}")
    endif()
    list(FIND COURSE_SOFTPIPE_CI ${test} ci)
    if(ci EQUAL -1)
      set(configurations CONFIGURATIONS softpipe)
      set(labels softpipe)
    else()
      set(configurations "")
      set(labels "softpipe;softpipe-ci")
    endif()
    add_test(NAME softpipe.${test} ${configurations}
      COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/softpipe/run_softpipe.sh ${kind}
              $<TARGET_FILE:imgdiff> ${COURSE_TEST_OUT}/softpipe ${head} ${tolerance} ${fraction} ${args}
      WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
    set(environment GALLIUM_DRIVER=softpipe)
    get_test_property(${test} ENVIRONMENT env)
    if(env)
      list(APPEND environment ${env})
    endif()
    get_property(unchecked GLOBAL PROPERTY COURSE_SOFTPIPE_UNCHECKED_${test})
    if(unchecked)
      list(APPEND environment "COURSE_SOFTPIPE_UNCHECKED=${unchecked}")
    endif()
    get_property(known GLOBAL PROPERTY COURSE_SOFTPIPE_KNOWN_${test})
    if(known)
      list(APPEND environment "COURSE_SOFTPIPE_KNOWN=${known}")
    endif()
    set_tests_properties(softpipe.${test} PROPERTIES LABELS "${labels}" SKIP_RETURN_CODE 77
      ENVIRONMENT "${environment}")
    # What makes a "differs" test pass is the same on either driver.
    foreach(property PASS_REGULAR_EXPRESSION FAIL_REGULAR_EXPRESSION WILL_FAIL)
      get_test_property(${test} ${property} value)
      if(value)
        if(known)
          message(SEND_ERROR "tests/softpipe/softpipe.cmake: ${test} has ${property}: "
                             "a known difference cannot invert it")
        endif()
        set_tests_properties(softpipe.${test} PROPERTIES ${property} "${value}")
      endif()
    endforeach()
    if(known)
      set_tests_properties(softpipe.${test} PROPERTIES PASS_REGULAR_EXPRESSION "imgdiff: .*-> FAIL")
    endif()
  endforeach()
  # A name in this file that is no longer a golden or agreement test (renamed, or its package missing).
  get_property(named GLOBAL PROPERTY COURSE_SOFTPIPE_NAMED)
  foreach(test ${named} ${COURSE_SOFTPIPE_CI})
    list(FIND tests ${test} found)
    if(found EQUAL -1)
      message(WARNING "tests/softpipe/softpipe.cmake names ${test}, which is not a golden or agreement test")
    endif()
  endforeach()
endfunction()
cmake_language(DEFER CALL course_softpipe_register_all)

# The wrapper itself, without GL: a fake chapter on llvmpipe, on no context, with one side
# elsewhere or refusing what the context lacks is skipped and compares nothing; a difference fails.
add_test(NAME softpipe.self_check
  COMMAND ${BASH} ${CMAKE_SOURCE_DIR}/tests/softpipe/run_self_check.sh ${CMAKE_SOURCE_DIR})
set_tests_properties(softpipe.self_check PROPERTIES LABELS "unit;softpipe;softpipe-ci")
