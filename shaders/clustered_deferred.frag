#version 330 core
// clustered_deferred.frag - chapter 11's clustered deferred shading pass: one full-screen triangle;
// each pixel reads its surface from the G-buffer once, finds its cluster (clusters.glsl) and adds
// up that cluster's lights in registers, ambient first; the sum is written once: no blending.
// Background pixels write the forward renderer's clear colour and loop over nothing.
#include "shading.glsl"
#include "gbuffer_read.glsl"
#include "heat.glsl"
#include "clusters.glsl"

uniform int u_view_mode;      // SHADER_VIEW_LIT, SHADER_VIEW_OVERDRAW, VIEW_CLUSTERS, VIEW_COUNT
uniform bool u_output_linear; // linear radiance for a float target (the benchmark)

out vec4 o_color;

void main()
{
    surface s = gbuffer_read(ivec2(gl_FragCoord.xy));
    if (s.background) {
        o_color = u_view_mode == VIEW_COUNT ? vec4(0.0) : vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    float depth = cluster_view_depth(s.position);
    ivec2 range = cluster_range(cluster_index(gl_FragCoord.xy, depth));
    vec3 c = vec3(0.0);
    if (u_view_mode == SHADER_VIEW_LIT) {
        vec3 v = safe_normalize(u_eye - s.position, s.normal);
        c = cluster_shade(range, s.position, s.normal, v, s.albedo, s.specular, s.shininess, s.occlusion) +
            s.emissive;
    }
    o_color = cluster_output(u_view_mode, u_output_linear, range, depth, c);
}
