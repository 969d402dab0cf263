#version 330 core
// light_volume.frag - one light at one pixel: read the surface from the G-buffer and call
// shade_light() with exactly the arguments forward.frag gives it.
// With OVERWRITE (chapters 04-05: no blending, straight into the 8-bit target) this fragment
// replaces the pixel, so it carries the ambient term too and display-encodes its result. Without it
// (chapter 06 on) it writes linear radiance to be added up. Only OVERWRITE discards: a shader
// without discard lets llvmpipe run the depth test before the shader.
#include "shading.glsl"
#include "gbuffer_read.glsl"

flat in vec3 v_light_position;
flat in float v_light_radius;
flat in vec3 v_light_radiance;
flat in vec3 v_light_attenuation;
flat in vec3 v_light_direction;
flat in vec2 v_light_cos;
flat in float v_volume_radius;

uniform int u_view; // SHADER_VIEW_LIT, _RING (lit + cut-off ring) or _OVERDRAW (one count per fragment)

out vec4 o_color;

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    // Depth alone says whether the surface is inside the sphere: the rest of the G-buffer is only
    // read for pixels the light reaches.
    float depth = texelFetch(u_gbuffer_depth, pixel, 0).r;
    vec3 position = gbuffer_position(pixel, depth);
    float d = length(v_light_position - position);
    // Derivatives while every fragment is still running (u_view is uniform: the branch is too).
    float ring_width = 0.0;
    if (u_view == SHADER_VIEW_RING)
        ring_width = 1.5 * fwidth(d);
    // Overdraw: this fragment ran, whatever it finds (background included); added up with blending.
    if (u_view == SHADER_VIEW_OVERDRAW) {
        o_color = vec4(vec3(1.0 / float(SHADER_OVERDRAW_SCALE)), 1.0);
        return;
    }
    if (depth >= 1.0 || d > v_volume_radius) {
#ifdef OVERWRITE
        discard;
#else
        o_color = vec4(0.0);
        return;
#endif
    }
    surface s = gbuffer_read_at(pixel, depth, position);
    light_data L = light_data(v_light_position, v_light_radius, v_light_radiance, v_light_attenuation);
    vec3 n = s.normal;
    vec3 v = safe_normalize(u_eye - s.position, n);
    light_cone C = light_cone(v_light_direction, v_light_cos.x, v_light_cos.y);
    vec3 c = shade_light(L, C, s.position, n, v, s.albedo, s.specular, s.shininess);
#ifdef OVERWRITE
    c += shade_ambient(s.albedo * s.occlusion);
    c += s.emissive;
#endif
    if (u_view == SHADER_VIEW_RING && v_volume_radius - d < ring_width)
        c += L.radiance / max(max(L.radiance.r, L.radiance.g), max(L.radiance.b, 1e-6));
#ifdef OVERWRITE
    c = display_encode(c);
#endif
    o_color = vec4(c, 1.0);
}
