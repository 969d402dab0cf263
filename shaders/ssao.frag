#version 330 core
// ssao.frag - chapter 17's screen-space ambient occlusion, one full-screen pass: for each pixel, its
// surface from the G-buffer (or forward's depth-normal pre-pass: the same encoding), then u_samples
// directions in the hemisphere around its normal (cosine-weighted, turned by this pixel's angle from
// the 4 x 4 noise tile), each marched in SHADER_AO_STEPS points up to u_radius. A point is hidden
// when it lies behind the surface the G-buffer holds at its pixel (that surface's plane), unless
// that surface is more than the radius in front of it (a foreground object, not an occluder). A direction with a hidden point is
// occluded; the output is the share of open directions, 1 for the background.
#include "gbuffer_read.glsl"

uniform mat4 u_view_proj;
uniform vec3 u_kernel[SHADER_AO_MAX_SAMPLES]; // unit directions, z along the normal (chapter's C)
uniform int u_samples;
uniform float u_radius;
uniform sampler2D u_noise; // RG32F, SHADER_AO_NOISE_SIZE^2 texels: (cos, sin) of each pixel's turn

out vec4 o_ao;

// Whether the march along d from p meets a surface of the depth buffer (off screen: open).
bool occluded(vec3 p, vec3 d)
{
    for (int j = 1; j <= SHADER_AO_STEPS; j++) {
        vec4 clip = u_view_proj * vec4(p + d * (u_radius * float(j) / float(SHADER_AO_STEPS)), 1.0);
        vec2 w = (clip.xy / clip.w * 0.5 + 0.5) * u_viewport_size;
        if (clip.w <= 0.0 || any(lessThan(w, vec2(0.0))) || any(greaterThanEqual(w, u_viewport_size)))
            return false;
        ivec2 pixel = ivec2(w);
        float depth = texelFetch(u_gbuffer_depth, pixel, 0).r;
        if (gbuffer_is_background(depth))
            continue;
        vec3 q = p + d * (u_radius * float(j) / float(SHADER_AO_STEPS));
        vec3 seen = gbuffer_position(pixel, depth);
        vec3 normal = gbuffer_decode(vec4(0.0), texelFetch(u_gbuffer_normal, pixel, 0), depth, seen).normal;
        // behind the plane of the surface seen there (not its depth at the pixel's centre, which a
        // grazing floor changes by more than a radius across one pixel), and not far behind it
        float gap = clip.w - (u_view_proj * vec4(seen, 1.0)).w;
        if (dot(q - seen, normal) < -0.02 * u_radius && gap < u_radius)
            return true;
    }
    return false;
}

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(u_gbuffer_depth, pixel, 0).r;
    if (gbuffer_is_background(depth)) {
        o_ao = vec4(1.0);
        return;
    }
    surface s = gbuffer_read_at(pixel, depth, gbuffer_position(pixel, depth));
    vec3 n = s.normal;
    vec3 t0 = normalize(cross(abs(n.x) < 0.5 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0), n));
    vec2 turn = texelFetch(u_noise, pixel % SHADER_AO_NOISE_SIZE, 0).xy;
    vec3 t = turn.x * t0 + turn.y * cross(n, t0);
    vec3 b = cross(n, t);
    int hidden = 0;
    for (int i = 0; i < u_samples; i++) {
        vec3 k = u_kernel[i];
        hidden += occluded(s.position, k.x * t + k.y * b + k.z * n) ? 1 : 0;
    }
    o_ao = vec4(vec3(1.0 - float(hidden) / float(u_samples)), 1.0);
}
