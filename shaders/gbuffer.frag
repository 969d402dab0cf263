#version 330 core
// gbuffer.frag - the geometry pass: no lighting, only what the lighting pass will need,
// written to two render targets at once (vertex shader: forward.vert, so depth is bit-identical).
// GBUFFER_NORMAL (a SHADER_GBUFFER_NORMAL_* value, set by common/render/gbuffer.c from the layout) says how
// RT1 holds the normal; shaders/gbuffer_read.glsl undoes each. GBUFFER_EXACT: the benchmark's
// reference instead, the float position and normal into two float targets. GBUFFER_EMISSIVE (a scene
// with emissive materials, common/render/gbuffer.h): a third target, RT2, the surface's emissive.
#include "shading.glsl"
#include "octahedral.glsl"
#include "gbuffer_encode.glsl"
#include "material_maps.glsl"

#ifndef GBUFFER_NORMAL
#define GBUFFER_NORMAL SHADER_GBUFFER_NORMAL_HALF
#endif

in vec3 v_world;
in vec3 v_normal;
flat in vec3 v_albedo;
flat in float v_specular;
flat in float v_shininess;

layout(location = 0) out vec4 o_albedo;           // GL_COLOR_ATTACHMENT0: albedo (+ specular in a)
layout(location = 1) out vec4 o_normal_material;  // GL_COLOR_ATTACHMENT1: normal (+ material)
#ifdef GBUFFER_EMISSIVE
layout(location = 2) out vec4 o_emissive;         // GL_COLOR_ATTACHMENT2: emissive (RGBA16F)
#endif

void main()
{
    // Same fallback as forward.frag, so a degenerate normal shades the same in both renderers.
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0));
    // A metallic-roughness material's images (chapter 18): forward.frag applies the same.
    vec3 albedo = v_albedo;
    float specular = v_specular, shininess = v_shininess, occlusion;
    material_apply_maps(albedo, specular, shininess, n, occlusion);
#ifdef GBUFFER_EMISSIVE
    o_emissive = vec4(material_emissive(), 1.0);
#endif
#if defined(GBUFFER_EXACT)
    o_albedo = vec4(v_world, 1.0);
    o_normal_material = vec4(n, 1.0);
#elif GBUFFER_NORMAL == SHADER_GBUFFER_NORMAL_HALF
    // linear; GL_FRAMEBUFFER_SRGB encodes it on write. a: the occlusion (1 but for an occlusion map),
    // never sRGB-encoded. A metallic-roughness material's metallic and -1 - roughness ride in z and w.
    o_albedo = vec4(albedo, occlusion);
    o_normal_material = vec4(octahedral_encode_half(n), specular, shininess);
#else
    o_albedo = vec4(albedo, specular); // alpha is never sRGB-encoded: specular stays linear
#if GBUFFER_NORMAL == SHADER_GBUFFER_NORMAL_BYTES
    o_normal_material = vec4(octahedral_encode_codes(n, 127.0) / 255.0, 0.0, shininess_store(shininess));
#elif GBUFFER_NORMAL == SHADER_GBUFFER_NORMAL_PACKED
    o_normal_material = vec4(pack_12_12(octahedral_encode_codes(n, 2047.0)), shininess_store(shininess));
#else // SHADER_GBUFFER_NORMAL_SHORTS
    // b: 0 for Blinn-Phong; a metallic-roughness material's occlusion as 0.5 + 0.5 o, with its
    // roughness in a to the 1/1024 steps pbr_roughness keeps (its metallic is RT0's 8-bit alpha)
    o_normal_material = vec4(octahedral_encode_codes(n, 32767.0) / 65535.0, 0.0, shininess_store(shininess));
    if (material_is_pbr(shininess))
        o_normal_material.zw = vec2(0.5 + 0.5 * occlusion, floor(clamp(-1.0 - shininess, 0.0, 1.0) * 1024.0 + 0.5) / 1024.0);
#endif
#endif
}
