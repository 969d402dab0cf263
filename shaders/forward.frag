#version 330 core
// forward.frag - shades a surface point with every light (or the object's light list).
// With TRANSPARENT (chapter 12's glass, common/render/forward.c): the output is linear radiance with the
// material's opacity A in alpha, for blending A * shaded + (1 - A) * behind over linear radiance;
// a back face (an object's far side, seen through its near side) is shaded as the side facing the eye.
#include "shading.glsl"
#include "material_maps.glsl"

in vec3 v_world;
in vec3 v_normal;
flat in int v_object;
flat in vec3 v_albedo;
flat in float v_specular;
flat in float v_shininess;

uniform vec3 u_eye;

// Per-object light lists (common/render/forward.c): entries 2*o and 2*o+1 hold object o's first index
// and count; the light indices follow.
uniform bool u_use_list;
uniform isamplerBuffer u_light_list;

out vec4 o_color;

#ifdef TRANSPARENT
uniform samplerBuffer u_objects; // the opacity: y of texel SHADER_OBJECT_TEXEL_OPACITY (forward.vert's)
uniform int u_view;              // SHADER_VIEW_OVERDRAW: count the fragment instead of shading it
#endif

void main()
{
#ifdef TRANSPARENT
    if (u_view == SHADER_VIEW_OVERDRAW) {
        o_color = vec4(vec3(1.0 / float(SHADER_OVERDRAW_SCALE)), 1.0);
        return;
    }
#endif
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0));
    vec3 albedo = v_albedo;
    float specular = v_specular, shininess = v_shininess, occlusion;
    material_apply_maps(albedo, specular, shininess, n, occlusion);
#ifdef TRANSPARENT
    if (!gl_FrontFacing)
        n = -n;
#endif
    vec3 v = safe_normalize(u_eye - v_world, n);
    vec3 c = shade_ambient_at(v_world, n, v, albedo, specular, shininess, occlusion);
    c += material_emissive(); // once per pixel, beside the ambient (0 but for an emissive material)
    int first = 0, count = u_light_count;
    if (u_use_list) {
        first = texelFetch(u_light_list, 2 * v_object).r;
        count = texelFetch(u_light_list, 2 * v_object + 1).r;
    }
    for (int k = 0; k < count; k++) {
        int i = u_use_list ? texelFetch(u_light_list, first + k).r : k;
        c += shade_light_index(i, v_world, n, v, albedo, specular, shininess);
    }
#if defined(TRANSPARENT)
    // Specular included: the whole shaded colour is weighted by A when blended.
    o_color = vec4(c, texelFetch(u_objects, SHADER_OBJECT_TEXELS * v_object + SHADER_OBJECT_TEXEL_OPACITY).y);
#elif defined(OUTPUT_LINEAR)
    o_color = vec4(c, 1.0); // linear radiance for a float target (the benchmark's HDR error)
#else
    o_color = vec4(display_encode(c), 1.0);
#endif
}
