#version 330 core
// forward.frag - shades a surface point with every light (or the object's light list).
#include "shading.glsl"

in vec3 v_world;
in vec3 v_normal;

uniform vec3 u_eye;
uniform vec3 u_albedo;
uniform float u_specular;
uniform float u_shininess;

uniform bool u_use_list;           // per-object light list instead of all lights
uniform isamplerBuffer u_light_list;
uniform int u_list_offset;
uniform int u_list_count;

out vec4 o_color;

void main()
{
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0));
    vec3 v = safe_normalize(u_eye - v_world, n);
    vec3 c = shade_ambient(u_albedo);
    int count = u_use_list ? u_list_count : u_light_count;
    for (int k = 0; k < count; k++) {
        int i = u_use_list ? texelFetch(u_light_list, u_list_offset + k).r : k;
        c += shade_light(light_fetch(i), v_world, n, v, u_albedo, u_specular, u_shininess);
    }
#ifdef OUTPUT_LINEAR
    o_color = vec4(c, 1.0); // linear radiance for a float target (the benchmark's HDR error)
#else
    o_color = vec4(display_encode(c), 1.0);
#endif
}
