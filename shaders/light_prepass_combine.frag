#version 330 core
// light_prepass_combine.frag - chapter 15's second geometry pass: every object drawn again, depth
// test GL_EQUAL against the thin pass's depth, so only the visible fragment runs; it meets the light
// buffer at its pixel with its own material: ambient + albedo * diffuse + specular * specular light.
// Mono (one specular channel, u_specular_rgb false): the specular light's colour is taken to be the
// diffuse light's, scaled to the stored luminance: right for one light, or lights of one colour.
// A metallic-roughness material's emissive (chapter 18) is added here, once, beside the ambient.
#include "shading.glsl"
#include "material_maps.glsl"

flat in vec3 v_albedo;
flat in float v_specular;

uniform sampler2D u_light_diffuse;  // RGBA16F: diffuse light RGB, specular luminance in A
uniform sampler2D u_light_specular; // RGBA16F: specular light RGB (rgb mode only)
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
    vec3 c = u_view == VIEW_DIFFUSE_LIGHT    ? d.rgb
             : u_view == VIEW_SPECULAR_LIGHT ? s
                                             : shade_ambient(v_albedo) + material_emissive() + v_albedo * d.rgb + v_specular * s;
    o_color = u_output_linear ? vec4(c, 1.0) : vec4(display_encode(c), 1.0);
}
