// material_pbr.glsl - chapter 18's metallic-roughness material (docs/18_pbr_materials.md): GGX with
// Smith's height-correlated visibility, Schlick's Fresnel and an energy-weighted Lambert diffuse.
// Included through shading_features.glsl in programs built for a scene with such materials
// (MATERIAL_PBR), and by the shaders that take its factors apart (chapter 15's light buffer,
// chapter 18's channel views). Include after "shading.glsl".
#ifndef MATERIAL_PBR_GLSL
#define MATERIAL_PBR_GLSL

// Every renderer hands a surface's material to the shading functions as (albedo, specular, shininess).
// Blinn-Phong's shininess is positive; a metallic-roughness material travels in the same three values
// with a negative shininess: specular = metallic, shininess = -1 - roughness. One signature, so no
// renderer's loop changes, and a scene of one model builds only its code (shading_features.glsl).
const float PI = 3.14159265358979;
// Perceptual roughness is clamped here: below it GGX's peak (1 / (pi alpha^2)) outgrows a float's
// useful range for the highlight of a point light, and roughness 0 would be 0 / 0 at n.h = 1.
const float PBR_ROUGHNESS_MIN = 0.045;

// The values the G-buffer keeps, so forward and deferred shade the same numbers: metallic to 8 bits,
// roughness to the 1/1024 steps a half float holds -1 - roughness in.
float pbr_metallic(float specular)
{
    return floor(clamp(specular, 0.0, 1.0) * 255.0 + 0.5) / 255.0;
}

float pbr_roughness(float shininess)
{
    float r = floor(clamp(-1.0 - shininess, 0.0, 1.0) * 1024.0 + 0.5) / 1024.0;
    return max(r, PBR_ROUGHNESS_MIN);
}

// pbr_brdf's factors that know only the roughness and the directions (chapter 15's light buffer sums
// them before the material): GGX's D and the visibility V, a2 = alpha^2 = roughness^4, n.l > 0.
void pbr_distribution_visibility(float ndl, float ndv, float ndh, float a2, out float D, out float V)
{
    float d = ndh * ndh * (a2 - 1.0) + 1.0;
    D = a2 / (PI * d * d);
    V = 0.5 / (ndl * sqrt(ndv * ndv * (1.0 - a2) + a2) + ndv * sqrt(ndl * ndl * (1.0 - a2) + a2));
}

// alpha^2 from the material's shininess (-1 - roughness).
float pbr_alpha2(float shininess)
{
    float alpha = pbr_roughness(shininess);
    alpha *= alpha;
    return alpha * alpha;
}

// A normal turned from the eye (interpolation, a normal map) gives n.v <= 0: taken as grazing.
float pbr_ndv(vec3 n, vec3 v)
{
    return clamp(dot(n, v), 1e-4, 1.0);
}

// pi times the metallic-roughness BRDF for unit n, v, l with n.l > 0: GGX distribution D, Smith's
// height-correlated visibility V (D V is D G / (4 n.l n.v)), Schlick's Fresnel F with F0 = mix(0.04,
// base, metallic), and Lambert's diffuse times (1 - metallic), weighted by what Fresnel lets into the
// surface at the light's angle and out of it at the eye's, (1 - F(n.l))(1 - F(n.v)): so a white surface
// never returns more light than it receives (tests/unit/test_brdf_furnace.c). pi times, because the
// course's lights are scaled so a white Lambert surface facing a light returns its radiance E
// (Blinn-Phong's E n.l albedo).
vec3 pbr_brdf(vec3 n, vec3 v, vec3 l, vec3 base, float specular, float shininess)
{
    float metallic = pbr_metallic(specular);
    float a2 = pbr_alpha2(shininess);
    vec3 h = safe_normalize(l + v, n);
    float ndl = clamp(dot(n, l), 0.0, 1.0);
    float ndv = pbr_ndv(n, v);
    float ndh = clamp(dot(n, h), 0.0, 1.0);
    float vdh = clamp(dot(v, h), 0.0, 1.0);
    float D, V;
    pbr_distribution_visibility(ndl, ndv, ndh, a2, D, V);
    vec3 f0 = mix(vec3(0.04), base, metallic);
    vec3 F = f0 + (1.0 - f0) * pow(1.0 - vdh, 5.0);
    vec3 into = (1.0 - f0) * (1.0 - pow(1.0 - ndl, 5.0)); // 1 - F(n.l)
    vec3 out_of = (1.0 - f0) * (1.0 - pow(1.0 - ndv, 5.0)); // 1 - F(n.v)
    return into * out_of * (1.0 - metallic) * base + PI * D * V * F;
}

// What light L brings to a metallic-roughness surface: E f (n.l) pbr_brdf.
vec3 pbr_light(light_reach r, vec3 radiance, vec3 n, vec3 v, vec3 albedo, float specular, float shininess)
{
    return r.f * radiance * r.ndl * pbr_brdf(n, v, r.l, albedo, specular, shininess);
}

#endif
