#version 330 core
// msaa_resolve.frag - chapter 13's resolve of the forward renderers' multisampled linear picture
// (MSAA_SAMPLES samples; without MSAA_MULTISAMPLE a plain texture, read as is): one value per pixel,
// the mean of its samples, in linear radiance, as the deferred edge pass averages its samples. The
// display encoding comes after, once, in accum_present.frag.
// variants: MSAA_SAMPLES 1 | MSAA_SAMPLES 4, MSAA_MULTISAMPLE 1
#ifdef MSAA_MULTISAMPLE
uniform sampler2DMS u_image;
#else
uniform sampler2D u_image;
#endif

out vec4 o_color;

void main()
{
    vec3 sum = vec3(0.0);
    for (int s = 0; s < MSAA_SAMPLES; s++)
        sum += texelFetch(u_image, ivec2(gl_FragCoord.xy), s).rgb; // sample s (plain: mip level 0)
    o_color = vec4(sum / float(MSAA_SAMPLES), 1.0);
}
