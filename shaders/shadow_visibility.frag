#version 330 core
// shadow_visibility.frag - chapter 14's visibility view (--view visibility): for each pixel of the
// G-buffer, the share of the lights reaching it that the shadow maps let through, in red (1: all of
// them, 0: none), and in green whether any light reaches it at all (1) or none (0: nothing to shadow);
// with --view-light K (u_view_light >= 0), light K alone.
// The test against an exact shadow ray reads it (tests/shadows/test_shadow_reference.c).
// Built with SHADOWS only: shade_light_index() is shadowed, shade_light() is not.
// variants: SHADOWS 1
#include "shading.glsl"
#include "gbuffer_read.glsl"

uniform int u_view_light; // -1: every light

out vec4 o_color;

void main()
{
    surface s = gbuffer_read(ivec2(gl_FragCoord.xy));
    if (s.background) {
        o_color = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    vec3 v = safe_normalize(u_eye - s.position, s.normal);
    float reaching = 0.0, visible = 0.0;
    for (int i = 0; i < u_light_count; i++) {
        if (u_view_light >= 0 && i != u_view_light)
            continue;
        light_data L = light_fetch(i);
        if (shade_light(L, light_fetch_cone(i), s.position, s.normal, v, vec3(1.0), 0.0, 1.0) == vec3(0.0))
            continue;
        reaching += 1.0;
        visible += shadow_visibility(i, L.position, s.position, s.normal);
    }
    o_color = vec4(reaching > 0.0 ? visible / reaching : 0.0, reaching > 0.0 ? 1.0 : 0.0, 0.0, 1.0);
}
