#version 330 core
// light_prepass_thin.frag - chapter 15's thin pass (the light pre-pass's first geometry pass): only
// what the lights need, the normal and the shininess, in ONE target (the compact G-buffer's RT1,
// packed the same way); the albedo and the specular strength wait for the second geometry pass.
// Vertex shader: forward.vert, so the depth is the one the second pass tests for equality.
#include "shading.glsl"
#include "octahedral.glsl"
#include "gbuffer_encode.glsl"

in vec3 v_world;
in vec3 v_normal;
flat in float v_shininess;

out vec4 o_normal_shininess; // GL_RGBA8: octahedral 2 x 12 bits in r, g, b; shininess in a

void main()
{
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0)); // forward.frag's fallback
    o_normal_shininess = vec4(pack_12_12(octahedral_encode_codes(n, 2047.0)), shininess_store(v_shininess));
}
