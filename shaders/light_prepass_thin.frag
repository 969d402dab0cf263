#version 330 core
// light_prepass_thin.frag - chapter 15's thin pass (the light pre-pass's first geometry pass): only
// what the lights need, the normal and the shininess, in ONE target (the compact G-buffer's RT1,
// packed the same way); the albedo and the specular strength wait for the second geometry pass.
// LIGHT_PREPASS_PBR (a scene with metallic-roughness materials): the normal after the normal map and
// the shininess after the metal-rough map (-1 - roughness, negative: Blinn-Phong's stays positive),
// both as half floats in one GL_RGBA16F target, the compact G-buffer's reference layout's RT1.
// Vertex shader: forward.vert, so the depth is the one the second pass tests for equality.
#include "shading.glsl"
#include "octahedral.glsl"
#include "gbuffer_encode.glsl"
#ifdef LIGHT_PREPASS_PBR
#include "material_maps.glsl"
#endif

in vec3 v_world;
in vec3 v_normal;
flat in float v_shininess;
#ifdef LIGHT_PREPASS_PBR
flat in vec3 v_albedo;
flat in float v_specular;
#endif

out vec4 o_normal_shininess; // GL_RGBA8: octahedral 2 x 12 bits in r, g, b; shininess in a
                             // LIGHT_PREPASS_PBR: GL_RGBA16F, octahedral in r, g; shininess in b

void main()
{
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0)); // forward.frag's fallback
#ifdef LIGHT_PREPASS_PBR
    // forward.frag's call: of its results only n and the shininess are written, so the compiler
    // drops the base colour's and the occlusion's reads; the lights need the normal and metal-rough maps.
    vec3 albedo = v_albedo;
    float specular = v_specular, shininess = v_shininess, occlusion;
    material_apply_maps(albedo, specular, shininess, n, occlusion);
    o_normal_shininess = vec4(octahedral_encode_half(n), shininess, 0.0);
#else
    o_normal_shininess = vec4(pack_12_12(octahedral_encode_codes(n, 2047.0)), shininess_store(v_shininess));
#endif
}
