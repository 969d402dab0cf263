#version 330 core
// ibl_view.frag - chapter 19's views, from the G-buffer (built with IMAGE_BASED_LIGHT):
//   probe       which probe lights each pixel: the colour of the one weighing most, darker where the
//               probes cover less (black: outside every radius, the constant ambient)
//   irradiance  the probes' irradiance E / pi alone (a white Lambertian surface's ambient)
//   specular    the probes' specular term alone: prefiltered radiance times (F0 A + B)
// variants: IMAGE_BASED_LIGHT 1
#include "shading.glsl"
#include "gbuffer_read.glsl"

uniform int u_ibl_view; // 1 probe, 2 irradiance, 3 specular
uniform int u_probe_scene_index[SHADER_IBL_MAX_PICKED];

out vec4 o_color;

vec3 probe_colour(int k)
{
    const vec3 palette[6] = vec3[6](vec3(0.9, 0.25, 0.2), vec3(0.25, 0.8, 0.3), vec3(0.25, 0.4, 0.95),
                                    vec3(0.95, 0.8, 0.2), vec3(0.8, 0.3, 0.9), vec3(0.2, 0.85, 0.9));
    return palette[k % 6];
}

void main()
{
    surface s = gbuffer_read(ivec2(gl_FragCoord.xy));
    if (s.background) {
        o_color = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    vec3 v = safe_normalize(u_eye - s.position, s.normal);
    float roughness = ibl_roughness(s.shininess);
    ibl_terms t = ibl_gather(s.position, s.normal, v, roughness);
    vec3 c;
    if (u_ibl_view == 1) {
        c = t.strongest < 0 ? vec3(0.0) : probe_colour(u_probe_scene_index[t.strongest]) * (0.35 + 0.65 * min(t.coverage, 1.0));
        o_color = vec4(c, 1.0);
        return;
    }
    vec2 ab = ibl_brdf(s.normal, v, roughness);
    c = u_ibl_view == 2 ? t.irradiance : t.prefiltered * (s.specular * ab.x + ab.y);
    o_color = vec4(display_encode(min(t.coverage, 1.0) * c), 1.0);
}
