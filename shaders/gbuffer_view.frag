#version 330 core
// gbuffer_view.frag - shows one G-buffer target as a picture (chapter 02's --view).
// Colour data is display-encoded like a lit image; the other targets are data, shown raw. The two
// RAW views write the decoded normal or the rebuilt position into a float target, for the
// benchmark's precision sweep (tools/bench/bench_gbuffer.c).
#include "shading.glsl"
#include "gbuffer_read.glsl"


uniform int u_view;
uniform vec2 u_near_far;

out vec4 o_color;

// Window depth back to view-space distance: inverts the perspective's z row (glm_perspective);
// reversed-Z stores d = n (f - z) / (z (f - n)) instead (docs/02_mrt_gbuffer.md).
float linear_depth(float depth)
{
    float n = u_near_far.x, f = u_near_far.y;
    if (u_gbuffer_reversed_z)
        return n * f / (depth * (f - n) + n);
    float z_ndc = depth * 2.0 - 1.0;
    return 2.0 * n * f / (f + n - z_ndc * (f - n));
}

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    surface s = gbuffer_read(ivec2(gl_FragCoord.xy));
    vec3 c = vec3(0.0);
    if (u_view == SHADER_GBUFFER_VIEW_ALBEDO) {
        c = display_encode(s.albedo);
    } else if (u_view == SHADER_GBUFFER_VIEW_NORMAL) {
        c = s.normal * 0.5 + 0.5; // world-space axes: +x red, +y green, +z blue
    } else if (u_view == SHADER_GBUFFER_VIEW_DEPTH) {
        float z = linear_depth(texelFetch(u_gbuffer_depth, pixel, 0).r);
        c = vec3((z - u_near_far.x) / (u_near_far.y - u_near_far.x)); // near black, far white
    } else if (u_view == SHADER_GBUFFER_VIEW_SPECULAR) {
        c = vec3(s.specular);
    } else if (u_view == SHADER_GBUFFER_VIEW_NORMAL_RAW) {
        o_color = vec4(s.normal, s.background ? 0.0 : 1.0); // a float target: the decoded numbers
        return;
    } else if (u_view == SHADER_GBUFFER_VIEW_POSITION_RAW) {
        o_color = vec4(s.position, s.background ? 0.0 : 1.0);
        return;
    }
    if (s.background && u_view != SHADER_GBUFFER_VIEW_DEPTH)
        c = vec3(0.0);
    o_color = vec4(c, 1.0);
}
