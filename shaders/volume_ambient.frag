#version 330 core
// volume_ambient.frag - the first thing in the light accumulation buffer: ambient light once per
// covered pixel (the background is discarded and stays black), in linear radiance.
#include "shading.glsl"
#include "gbuffer_read.glsl"

out vec4 o_color;

void main()
{
    surface s = gbuffer_read(ivec2(gl_FragCoord.xy));
    if (s.background)
        discard;
    o_color = vec4(shade_ambient(s.albedo), 1.0);
}
