#version 330 core
// forward.vert - object space to clip space for every pass that draws the scene's objects:
// the forward renderer, its depth pre-pass and the G-buffer pass. One vertex path means
// bit-identical depth everywhere, so GL_EQUAL after a pre-pass keeps every pixel (`invariant`
// makes that a promise rather than luck).
//
// Objects are drawn instanced, a batch of objects sharing a mesh per draw call; each instance
// reads its world matrix and material from u_objects (common/gl/gpu_scene.h lists the texels).

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;      // chapter 18: the texture coordinate
layout(location = 3) in vec4 a_tangent; // xyz, and w the handedness (common/scene/mesh_data.h)

uniform samplerBuffer u_objects;
uniform int u_first_object;
uniform mat4 u_view_proj;

out vec3 v_world;
out vec3 v_normal;
flat out int v_object;
flat out vec3 v_albedo;
flat out float v_specular;
flat out float v_shininess;
// What a material's images and its emissive need (shaders/material_maps.glsl), in programs built for
// a scene that has them (scene_features.glsl).
#include "scene_features.glsl"
#ifdef MATERIAL_MAPS
out vec2 v_uv;
out vec4 v_tangent;      // world space, w the handedness
flat out vec4 v_maps;    // the material's map layers
#endif
#ifdef MATERIAL_EMISSIVE
flat out vec4 v_emissive;
#endif
invariant gl_Position;

void main()
{
    int object = u_first_object + gl_InstanceID;
    int t = SHADER_OBJECT_TEXELS * object; // layout: common/base/shader_layout.h
    mat4 model = mat4(texelFetch(u_objects, t), texelFetch(u_objects, t + 1), texelFetch(u_objects, t + 2),
                      texelFetch(u_objects, t + 3));
    int n = t + SHADER_OBJECT_TEXEL_NORMAL;
    mat3 normal_matrix = mat3(texelFetch(u_objects, n).xyz, texelFetch(u_objects, n + 1).xyz,
                              texelFetch(u_objects, n + 2).xyz);
    vec4 material = texelFetch(u_objects, t + SHADER_OBJECT_TEXEL_MATERIAL);

    vec4 world = model * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = normal_matrix * a_normal;
    v_object = object;
    v_albedo = material.rgb;
    v_specular = material.a;
    v_shininess = texelFetch(u_objects, t + SHADER_OBJECT_TEXEL_SHININESS).r;
#ifdef MATERIAL_MAPS
    v_uv = a_uv;
    v_tangent = vec4(mat3(model) * a_tangent.xyz, a_tangent.w);
    v_maps = texelFetch(u_objects, t + SHADER_OBJECT_TEXEL_MAPS);
#endif
#ifdef MATERIAL_EMISSIVE
    v_emissive = texelFetch(u_objects, t + SHADER_OBJECT_TEXEL_EMISSIVE);
#endif
    gl_Position = u_view_proj * world;
}
