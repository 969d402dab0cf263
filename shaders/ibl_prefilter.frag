#version 330 core
// ibl_prefilter.frag - chapter 19, at start: one mip level of one face of a probe's prefiltered
// cube. Each texel is the radiance seen around its direction r through a GGX lobe of the level's
// roughness, with n = v = r (the split sum's first factor), by importance sampling: u_samples half
// vectors drawn by D(h) (n.h), each read at the mip level whose texels cover its share of the sphere
// (filtered importance sampling), weighted by n.l.
#include "ibl_sample.glsl"

uniform samplerCube u_source; // the captured radiance, with its mip chain
uniform float u_source_size;  // its level 0's face size in texels
uniform int u_face;
uniform float u_size;         // this level's face size
uniform float u_roughness;
uniform int u_samples;

out vec4 o_color;

void main()
{
    vec3 r = ibl_cube_direction(u_face, gl_FragCoord.xy, u_size);
    if (u_roughness <= 0.0) { // a mirror: the radiance itself
        o_color = vec4(textureLod(u_source, r, 0.0).rgb, 1.0);
        return;
    }
    float alpha = u_roughness * u_roughness;
    float texel_angle = 4.0 * IBL_PI / (6.0 * u_source_size * u_source_size);
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    uint n = uint(u_samples);
    for (uint i = 0u; i < n; i++) {
        vec3 h = ibl_ggx_half(ibl_hammersley(i, n), r, alpha);
        vec3 l = reflect(-r, h);
        float ndl = dot(r, l);
        if (ndl <= 0.0)
            continue;
        float ndh = max(dot(r, h), 0.0);
        // pdf of l is D(h) (n.h) / (4 v.h), and v.h = n.h here
        float pdf = ibl_ggx_d(ndh, alpha) * 0.25;
        float sample_angle = 1.0 / (float(u_samples) * pdf + 1e-4);
        float lod = max(0.5 * log2(sample_angle / texel_angle) + 1.0, 0.0);
        sum += textureLod(u_source, l, lod).rgb * ndl;
        weight += ndl;
    }
    o_color = vec4(sum / max(weight, 1e-6), 1.0);
}
