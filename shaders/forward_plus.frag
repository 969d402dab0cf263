#version 330 core
// forward_plus.frag - chapter 11's clustered forward shading (Forward+): forward.frag's inputs, but
// each fragment loops over the lights of its cluster (clusters.glsl) instead of its object's list.
// Drawn after a depth pre-pass with GL_EQUAL, so each pixel runs the loop once.
// With TRANSPARENT (chapter 12's glass): as forward.frag's TRANSPARENT, linear radiance with the
// material's opacity in alpha, and a back face shaded as the side facing the eye; the glass fragment
// finds its cluster from its own depth, so the lists the opaque pass used light it too.
#include "shading.glsl"
#include "heat.glsl"
#include "clusters.glsl"
#include "material_maps.glsl"

in vec3 v_world;
in vec3 v_normal;
flat in int v_object;
flat in vec3 v_albedo;
flat in float v_specular;
flat in float v_shininess;

uniform vec3 u_eye;
uniform int u_view_mode;      // SHADER_VIEW_LIT, SHADER_VIEW_OVERDRAW, VIEW_CLUSTERS, VIEW_COUNT
uniform bool u_output_linear; // linear radiance for a float target (the benchmark)

out vec4 o_color;

#ifdef TRANSPARENT
uniform samplerBuffer u_objects; // the opacity: y of texel SHADER_OBJECT_TEXEL_OPACITY (forward.vert's)

void main()
{
    if (u_view_mode == SHADER_VIEW_OVERDRAW) { // the glass layers: one count per fragment
        o_color = vec4(vec3(1.0 / float(SHADER_OVERDRAW_SCALE)), 1.0);
        return;
    }
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0));
    vec3 albedo = v_albedo;
    float specular = v_specular, shininess = v_shininess, occlusion;
    material_apply_maps(albedo, specular, shininess, n, occlusion);
    if (!gl_FrontFacing)
        n = -n;
    vec3 v = safe_normalize(u_eye - v_world, n);
    ivec2 range = cluster_range(cluster_index(gl_FragCoord.xy, cluster_view_depth(v_world)));
    vec3 c = cluster_shade(range, v_world, n, v, albedo, specular, shininess, occlusion) + material_emissive();
    o_color = vec4(c, texelFetch(u_objects, SHADER_OBJECT_TEXELS * v_object + SHADER_OBJECT_TEXEL_OPACITY).y);
}
#else
void main()
{
    float depth = cluster_view_depth(v_world);
    ivec2 range = cluster_range(cluster_index(gl_FragCoord.xy, depth));
    vec3 c = vec3(0.0);
    if (u_view_mode == SHADER_VIEW_LIT) {
        vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0));
        vec3 albedo = v_albedo;
        float specular = v_specular, shininess = v_shininess, occlusion;
        material_apply_maps(albedo, specular, shininess, n, occlusion);
        vec3 v = safe_normalize(u_eye - v_world, n);
        c = cluster_shade(range, v_world, n, v, albedo, specular, shininess, occlusion) + material_emissive();
    }
    o_color = cluster_output(u_view_mode, u_output_linear, range, depth, c);
}
#endif
