#version 330 core
// gbuffer.frag - the geometry pass: no lighting, only what the lighting pass will need,
// written to two render targets at once (vertex shader: forward.vert, so depth is bit-identical).
#include "shading.glsl"
#include "octahedral.glsl"

in vec3 v_world;
in vec3 v_normal;
flat in vec3 v_albedo;
flat in float v_specular;
flat in float v_shininess;

layout(location = 0) out vec4 o_albedo;           // GL_COLOR_ATTACHMENT0, SRGB8_ALPHA8
layout(location = 1) out vec4 o_normal_material;  // GL_COLOR_ATTACHMENT1, RGBA16F

void main()
{
    // Same fallback as forward.frag, so a degenerate normal shades the same in both renderers.
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0));
    o_albedo = vec4(v_albedo, 1.0); // linear; GL_FRAMEBUFFER_SRGB encodes it on write
    o_normal_material = vec4(octahedral_encode_half(n), v_specular, v_shininess);
}
