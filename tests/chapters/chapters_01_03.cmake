# Chapters 01-03: the offscreen framebuffer, the G-buffer, the full-screen lighting pass.
# (Each chapter's default picture already has its golden test from golden.cmake.)
function(chapters_01_03_tests)
  if(TARGET 01_fbo_setup AND TARGET 00_forward)
    # Drawing into our own framebuffer and copying it texel for pixel changes nothing: exact.
    course_forward_agreement_test(01_vs_forward 0 0 01_fbo_setup)
  endif()

  if(TARGET 02_mrt_gbuffer)
    # One golden per G-buffer view (the default view, albedo, is golden.02_mrt_gbuffer).
    foreach(view normal depth specular final)
      course_golden_test(02_mrt_gbuffer_${view} 02_mrt_gbuffer 1 0.0001 --view ${view})
    endforeach()
  endif()

  if(TARGET 03_fullscreen_phong AND TARGET 00_forward)
    # Deferred matches forward to 1/255 on 99.99 % of pixels. Measured on llvmpipe: no pixel
    # differs by more than 1; the 1s come from the albedo's 8-bit sRGB storage (with RGBA32F
    # targets only 0.08 % of channels differ, by 1). docs/03_fullscreen_phong.md has the numbers.
    course_forward_agreement_test(03_vs_forward 1 0.0001 03_fullscreen_phong)
    # Another aspect ratio and size: the position rebuilt from depth uses the viewport size.
    course_forward_agreement_test(03_vs_forward_200x300 1 0.0001 03_fullscreen_phong --size 200x300)
    # The orange light has moved: light positions come from the same per-frame update.
    course_forward_agreement_test(03_vs_forward_time3 1 0.0001 03_fullscreen_phong --time 3)
    # The R key's other renderer is chapter 00's, bit for bit.
    course_agreement_test(03_renderer_forward 0 0 03_fullscreen_phong --renderer forward VS 00_forward)
    # The reach view: at cut-off 0.1 each light reaches part of the scene (the grey steps), and
    # at cut-off 0 every light reaches every pixel: white wherever a surface is.
    course_golden_test(03_fullscreen_phong_reach 03_fullscreen_phong 1 0.0001 --view reach --cutoff 0.1)
    course_golden_test(03_fullscreen_phong_reach_exact 03_fullscreen_phong 1 0.0001 --view reach --cutoff 0)
  endif()

  if(TARGET 02_mrt_gbuffer AND TARGET 03_fullscreen_phong)
    # Chapter 02's `final` view is chapter 03's lighting pass on the same G-buffer: exact.
    course_agreement_test(02_final_vs_03 0 0 02_mrt_gbuffer --view final VS 03_fullscreen_phong)
    # Chapter 02 makes its framebuffer by hand (mrt_create); in every layout it is gbuffer_create's:
    # the same picture to the byte.
    foreach(layout reference compact-d24s8 reversed-z linear-albedo oct8 oct16)
      course_agreement_test(02_final_vs_03_${layout} 0 0 02_mrt_gbuffer --view final --gbuffer ${layout}
                            VS 03_fullscreen_phong --gbuffer ${layout})
    endforeach()
  endif()
endfunction()
chapters_01_03_tests()
