#version 330 core
// ibl_brdf.frag - chapter 19, at start: the split sum's second factor, a table over (n.v, roughness)
// of the GGX specular BRDF integrated against a white environment, as a scale A and a bias B of F0
// (Schlick's Fresnel: F0 A + B). u_samples half vectors by importance; Smith's G in Schlick's form
// with k = alpha / 2. Texel (i, j) holds n.v = (i + 0.5) / size and roughness = (j + 0.5) / size.
#include "ibl_sample.glsl"

uniform float u_size;
uniform int u_samples;

out vec4 o_color;

float g1(float ndx, float k) { return ndx / (ndx * (1.0 - k) + k); }

void main()
{
    float ndv = gl_FragCoord.x / u_size;
    float roughness = gl_FragCoord.y / u_size;
    float alpha = roughness * roughness;
    vec3 n = vec3(0.0, 0.0, 1.0);
    vec3 v = vec3(sqrt(1.0 - ndv * ndv), 0.0, ndv);
    float k = alpha * 0.5;
    vec2 ab = vec2(0.0);
    uint count = uint(u_samples);
    for (uint i = 0u; i < count; i++) {
        vec3 h = ibl_ggx_half(ibl_hammersley(i, count), n, alpha);
        vec3 l = reflect(-v, h);
        float ndl = l.z, ndh = max(h.z, 0.0), vdh = max(dot(v, h), 0.0);
        if (ndl <= 0.0)
            continue;
        // f (n.l) / pdf = G (v.h) / ((n.h) (n.v)), pdf = D (n.h) / (4 v.h)
        float g = g1(ndv, k) * g1(ndl, k) * vdh / (ndh * ndv);
        float fc = pow(1.0 - vdh, 5.0);
        ab += vec2((1.0 - fc) * g, fc * g);
    }
    o_color = vec4(ab / float(count), 0.0, 1.0);
}
