#version 330 core
// accum_present.frag - the summed linear radiance to display values, once per pixel: optional
// tone mapping, then the same display_encode() the forward renderer applies. The overdraw view's
// buffer holds a count of lighting fragments instead: shown as a heat map (heat.glsl).
#include "shading.glsl"
#include "heat.glsl"

uniform sampler2D u_accum;
uniform int u_tonemap;    // SHADER_TONEMAP_NONE (clamp), _EXPOSURE or _REINHARD
uniform float u_exposure;
uniform int u_view;       // SHADER_VIEW_OVERDRAW: the buffer holds counts

out vec4 o_color;

void main()
{
    vec3 c = texelFetch(u_accum, ivec2(gl_FragCoord.xy), 0).rgb;
    if (u_view == SHADER_VIEW_OVERDRAW) {
        o_color = vec4(heat(overdraw_count(c.r)), 1.0);
        return;
    }
    if (u_tonemap != SHADER_TONEMAP_NONE)
        c *= u_exposure;
    if (u_tonemap == SHADER_TONEMAP_REINHARD)
        c = c / (1.0 + c);
    o_color = vec4(display_encode(c), 1.0);
}
