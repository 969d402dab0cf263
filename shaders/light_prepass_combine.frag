#version 330 core
// light_prepass_combine.frag - chapter 15's second geometry pass: every object drawn again, depth
// test GL_EQUAL against the thin pass's depth, so only the visible fragment runs; it meets the light
// buffer at its pixel with its own material: ambient + albedo * diffuse + specular * specular light.
// Mono (one specular channel, u_specular_rgb false): the specular light's colour is taken to be the
// diffuse light's, scaled to the stored luminance: right for one light, or lights of one colour.
// LIGHT_PREPASS_PBR (a scene with metallic-roughness materials; --specular rgb only): three targets,
// C, A and B (light_prepass_accum.frag); a metallic-roughness fragment finishes pbr_brdf with its own
// base colour and metallic (after their maps): (1 - F0)^2 (1 - metallic) base C + F0 A + B, and adds
// its emissive (chapter 18) once, beside the ambient (emissive exists only on such materials).
#include "shading.glsl"
#include "material_pbr.glsl"
#include "light_prepass.glsl"
#ifdef LIGHT_PREPASS_PBR
#include "material_maps.glsl"
#endif

flat in vec3 v_albedo;
flat in float v_specular;
#ifdef LIGHT_PREPASS_PBR
flat in float v_shininess;
#endif

uniform sampler2D u_light_diffuse;  // RGBA16F: diffuse light RGB, specular luminance in A
uniform sampler2D u_light_specular; // RGBA16F: specular light RGB (rgb mode only)
#ifdef LIGHT_PREPASS_PBR
uniform sampler2D u_light_fresnel;  // RGBA16F: B, the specular's Fresnel rise (metallic-roughness)
#endif
uniform bool u_specular_rgb;
uniform int u_view;                 // VIEW_LIT, VIEW_DIFFUSE_LIGHT, VIEW_SPECULAR_LIGHT
uniform bool u_output_linear;       // linear radiance for a float target (the benchmark)

#define VIEW_LIT 0
#define VIEW_DIFFUSE_LIGHT 1
#define VIEW_SPECULAR_LIGHT 2


out vec4 o_color;

// The specular light the buffer gives back: stored as RGB, or rebuilt from its luminance.
vec3 specular_light(vec4 d, ivec2 pixel)
{
    if (u_specular_rgb)
        return texelFetch(u_light_specular, pixel, 0).rgb;
    float y = dot(d.rgb, LUMINANCE);
    return y > 0.0 ? d.rgb * (d.a / y) : vec3(0.0);
}

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 d = texelFetch(u_light_diffuse, pixel, 0);
    vec3 s = specular_light(d, pixel);
#ifdef LIGHT_PREPASS_PBR
    // forward.frag's maps: the normal map's result is unused here (the light buffer has the normal's
    // part), so the compiler drops its read; base colour, metallic and occlusion are this pass's.
    vec3 albedo = v_albedo, n = vec3(0.0, 0.0, 1.0);
    float specular = v_specular, shininess = v_shininess, occlusion;
    material_apply_maps(albedo, specular, shininess, n, occlusion);
    vec3 b = texelFetch(u_light_fresnel, pixel, 0).rgb;
    vec3 lit = v_albedo * d.rgb + v_specular * s; // Blinn-Phong: b is 0
    if (material_is_pbr(shininess)) {
        float metallic = pbr_metallic(specular);
        vec3 f0 = mix(vec3(0.04), albedo, metallic);
        lit = (1.0 - f0) * (1.0 - f0) * (1.0 - metallic) * albedo * d.rgb + (f0 * s + b);
    }
    vec3 c = u_view == VIEW_DIFFUSE_LIGHT    ? d.rgb
             : u_view == VIEW_SPECULAR_LIGHT ? s + b
                                             : shade_ambient(albedo * occlusion) + material_emissive() + lit;
#else
    vec3 c = u_view == VIEW_DIFFUSE_LIGHT    ? d.rgb
             : u_view == VIEW_SPECULAR_LIGHT ? s
                                             : shade_ambient(v_albedo) + v_albedo * d.rgb + v_specular * s;
#endif
    o_color = u_output_linear ? vec4(c, 1.0) : vec4(display_encode(c), 1.0);
}
