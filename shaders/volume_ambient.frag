#version 330 core
// volume_ambient.frag - the first thing in the light accumulation buffer: ambient (and emissive) light once per
// covered pixel (the background is discarded and stays black), in linear radiance; with OVERWRITE
// (chapters 04-05, which draw straight into the 8-bit target) display-encoded.
#include "shading.glsl"
#include "gbuffer_read.glsl"

out vec4 o_color;

void main()
{
    surface s = gbuffer_read(ivec2(gl_FragCoord.xy));
    if (s.background)
        discard;
    vec3 c = shade_ambient(s.albedo * s.occlusion);
    c += s.emissive; // emissive: once per pixel, like the ambient (0 but for an emissive material)
#ifdef OVERWRITE
    c = display_encode(c);
#endif
    o_color = vec4(c, 1.0);
}
