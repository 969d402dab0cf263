#version 330 core
// ssao_blur.frag - chapter 17's blur of the raw occlusion: the mean over a 2N x 2N window
// (N = u_blur; N = 2 covers the 4 x 4 noise tile once, so each of its turns counts once) of the
// neighbours on this pixel's surface: near its tangent plane (within a tenth of the radius) and
// facing the same way (normals within about 25 degrees). Across a silhouette or a crease the other
// side is left out, so the occlusion does not bleed over edges.
#include "gbuffer_read.glsl"

uniform sampler2D u_ao_raw;
uniform int u_blur;
uniform float u_radius;

out vec4 o_ao;

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(u_gbuffer_depth, pixel, 0).r;
    if (gbuffer_is_background(depth)) {
        o_ao = vec4(1.0);
        return;
    }
    surface c = gbuffer_read_at(pixel, depth, gbuffer_position(pixel, depth));
    ivec2 size = ivec2(u_viewport_size);
    float sum = 0.0, count = 0.0;
    for (int y = -u_blur; y < u_blur; y++)
        for (int x = -u_blur; x < u_blur; x++) {
            ivec2 q = pixel + ivec2(x, y);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size)))
                continue;
            float d = texelFetch(u_gbuffer_depth, q, 0).r;
            if (gbuffer_is_background(d))
                continue;
            surface s = gbuffer_read_at(q, d, gbuffer_position(q, d));
            if (abs(dot(s.position - c.position, c.normal)) < 0.1 * u_radius && dot(s.normal, c.normal) > 0.9) {
                sum += texelFetch(u_ao_raw, q, 0).r;
                count += 1.0;
            }
        }
    o_ao = vec4(vec3(count > 0.0 ? sum / count : texelFetch(u_ao_raw, pixel, 0).r), 1.0);
}
