#version 330 core
// deferred_fullscreen.frag - the lighting pass: one full-screen triangle, every pixel reads its
// surface from the G-buffer and loops over all lights with the same shade_light() as forward.frag.
// VIEW_REACH (chapter 03's reach view): instead, the fraction of those lights that reach the pixel
// at all, display-encoded as grey: the rest of the loop returns zero, which chapter 04 avoids.
// VIEW_OVERDRAW (the overdraw view): the number of lights the loop below evaluates at the pixel, as a
// heat map (heat.glsl). It is the light count at every covered pixel: the loop has no way to skip.
#include "shading.glsl"
#include "gbuffer_read.glsl"
#include "heat.glsl"

out vec4 o_color;

void main()
{
    surface s = gbuffer_read(ivec2(gl_FragCoord.xy));
    // Nothing drawn here: keep the cleared black, and do not count the pixel as shaded.
    if (s.background)
        discard;
#ifdef VIEW_REACH
    int reached = 0;
    for (int i = 0; i < u_light_count; i++) {
        light_data L = light_fetch(i);
        reached += distance(L.position, s.position) <= L.radius ? 1 : 0;
    }
    o_color = vec4(display_encode(vec3(float(reached) / float(max(u_light_count, 1)))), 1.0);
    return;
#endif
    vec3 n = s.normal;
    vec3 v = safe_normalize(u_eye - s.position, n);
    vec3 c = shade_ambient(s.albedo * s.occlusion);
    c += s.emissive; // once per pixel, beside the ambient (0 but for an emissive material)
    int evaluated = 0;
    for (int i = 0; i < u_light_count; i++, evaluated++)
        c += shade_light(light_fetch(i), light_fetch_cone(i), s.position, n, v, s.albedo, s.specular, s.shininess);
#ifdef VIEW_OVERDRAW
    o_color = vec4(heat(evaluated), 1.0);
    return;
#endif
    o_color = vec4(display_encode(c), 1.0);
}
