#version 330 core
// light_prepass_accum.frag - chapter 15's light accumulation: one full-screen triangle; each pixel
// reads the thin pass's normal, shininess and depth, finds its cluster (chapter 11's lists) and adds
// up its lights' two terms, before any material (shade_light_terms): the diffuse light
// sum f E (n.l) and the specular light sum f E (n.h)^s. Written once, no blending:
//   target 0: diffuse RGB, and the specular sum's luminance in A (the mono light buffer)
//   target 1: the specular sum's RGB (--specular rgb only; mono leaves it unattached)
#include "shading.glsl"
#include "gbuffer_read.glsl"
#include "heat.glsl"
#include "clusters.glsl"

uniform sampler2D u_thin_normal; // RGBA8: light_prepass_thin.frag's packed normal and shininess
uniform sampler2D u_thin_depth;  // the thin pass's depth

layout(location = 0) out vec4 o_diffuse;
layout(location = 1) out vec4 o_specular;


void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(u_thin_depth, pixel, 0).r;
    o_diffuse = o_specular = vec4(0.0);
    if (gbuffer_is_background(depth))
        return;
    vec4 t = texelFetch(u_thin_normal, pixel, 0);
    vec3 p = gbuffer_position(pixel, depth);
    vec3 n = octahedral_decode_codes(gbuffer_unpack_12_12(t.xyz), 2047.0);
    float shininess = 1.0 + 255.0 * t.w; // shininess_store undone
    vec3 v = safe_normalize(u_eye - p, n);
    ivec2 range = cluster_range(cluster_index(gl_FragCoord.xy, cluster_view_depth(p)));
    vec3 diffuse = vec3(0.0), specular = vec3(0.0);
    int count = cluster_loop_count(range);
    for (int k = 0; k < count; k++)
        shade_light_terms(range.y < 0 ? k : texelFetch(u_cluster_lights, range.x + k).r, p, n, v, shininess,
                          diffuse, specular);
    o_diffuse = vec4(diffuse, dot(specular, LUMINANCE));
    o_specular = vec4(specular, 1.0);
}
