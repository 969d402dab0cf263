#version 330 core
// gbuffer.frag - the geometry pass: no lighting, only what the lighting pass will need,
// written to two render targets at once (vertex shader: forward.vert, so depth is bit-identical).
// GBUFFER_NORMAL (a SHADER_GBUFFER_NORMAL_* value, set by common/render/gbuffer.c from the layout) says how
// RT1 holds the normal; shaders/gbuffer_read.glsl undoes each. GBUFFER_EXACT: the benchmark's
// reference instead, the float position and normal into two float targets.
#include "shading.glsl"
#include "octahedral.glsl"
#include "gbuffer_encode.glsl"

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

void main()
{
    // Same fallback as forward.frag, so a degenerate normal shades the same in both renderers.
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0));
#if defined(GBUFFER_EXACT)
    o_albedo = vec4(v_world, 1.0);
    o_normal_material = vec4(n, 1.0);
#elif GBUFFER_NORMAL == SHADER_GBUFFER_NORMAL_HALF
    o_albedo = vec4(v_albedo, 1.0); // linear; GL_FRAMEBUFFER_SRGB encodes it on write (a unused)
    o_normal_material = vec4(octahedral_encode_half(n), v_specular, v_shininess);
#else
    o_albedo = vec4(v_albedo, v_specular); // alpha is never sRGB-encoded: specular stays linear
#if GBUFFER_NORMAL == SHADER_GBUFFER_NORMAL_BYTES
    o_normal_material = vec4(octahedral_encode_codes(n, 127.0) / 255.0, 0.0, shininess_store(v_shininess));
#elif GBUFFER_NORMAL == SHADER_GBUFFER_NORMAL_PACKED
    o_normal_material = vec4(pack_12_12(octahedral_encode_codes(n, 2047.0)), shininess_store(v_shininess));
#else // SHADER_GBUFFER_NORMAL_SHORTS
    o_normal_material = vec4(octahedral_encode_codes(n, 32767.0) / 65535.0, 0.0, shininess_store(v_shininess));
#endif
#endif
}
