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

uniform samplerBuffer u_objects;
uniform int u_first_object;
uniform mat4 u_view_proj;

out vec3 v_world;
out vec3 v_normal;
flat out int v_object;
flat out vec3 v_albedo;
flat out float v_specular;
flat out float v_shininess;
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
    gl_Position = u_view_proj * world;
}
